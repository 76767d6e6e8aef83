// An edit log replayed as `edgeland replay` does (el_replay_*): Landscape.ReplayLog.
using System;
using System.Text;

namespace Edgeland
{
    // A replayed edit log. The text is untrusted: a bad log is a replay that stopped, not an
    // exception. Dispose() frees its landscape.
    public sealed class Replay : IDisposable
    {
        // The replayed world, recording its own log from the start (so it can be edited and
        // shared again); null when the log has no good world line.
        public Landscape Landscape { get; private set; }
        // The edits applied.
        public ulong Edits { get; private set; }
        // Why the replay stopped before the log's end, or null: a LoadException for a line that
        // cannot be read or an edit the landscape refused (Index: the line, 1-based), an
        // InternalErrorException for a bug of edgeland's that an edit met.
        public EdgelandException Stopped { get; private set; }
        // The JSON object `edgeland replay` prints for the log (edits, polygons, ..., state_hash,
        // and stopped_at_line and error when it stopped).
        public string Report { get; private set; }

        const int LoadError = 23;  // EL_LOAD_ERROR: el_replay_landscape's "no world"

        Replay() { }

        internal static Replay Of(string log)
        {
            byte[] text = Encoding.UTF8.GetBytes(log);
            var e = Call.Error();
            ReplayHandle h;
            EdgelandException.Check(Native.el_replay_log(text, (UIntPtr)text.Length, out h, ref e), ref e);
            using (h)
            {
                var r = new Replay();
                e = Call.Error();
                r.Stopped = EdgelandException.Failure(Native.el_replay_stopped(h, ref e), ref e);
                r.Edits = (ulong)Native.el_replay_edits(h);
                r.Report = Encoding.UTF8.GetString(ReportOf(h));
                r.Landscape = LandscapeOf(h);
                return r;
            }
        }

        static byte[] ReportOf(ReplayHandle h)
        {
            var e = Call.Error();
            BytesHandle report;
            EdgelandException.Check(Native.el_replay_report(h, out report, ref e), ref e);
            return Results.Bytes(report);
        }

        // The replayed landscape, or null when the log had no world (EL_LOAD_ERROR).
        static Landscape LandscapeOf(ReplayHandle h)
        {
            var e = Call.Error();
            LandscapeHandle world;
            int status = Native.el_replay_landscape(h, out world, ref e);
            if (status == LoadError) { world.Dispose(); return null; }
            EdgelandException.Check(status, ref e);
            return Landscape.Own(world);
        }

        public void Dispose() { if (Landscape != null) Landscape.Dispose(); }
    }
}
