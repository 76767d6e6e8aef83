// edgeland's errors as exceptions, one class per el_status (the C++ class in brackets), each
// with the fields of the C API's el_error. A failed edit leaves the landscape as it was.
using System;
using System.Text;

namespace Edgeland
{
    public class EdgelandException : Exception
    {
        public const ulong None = ulong.MaxValue;
        public int Status { get; private set; }
        public uint Kind { get; private set; }      // the rule, setting or limit (edgeland.h)
        public uint Operand { get; private set; }
        public ulong Index { get; private set; }    // None when there is none
        public ulong Vertex { get; private set; }
        public long Value { get; private set; }
        public long Limit { get; private set; }
        public long Minimum { get; private set; }
        public Point Where { get; private set; }

        internal EdgelandException(int status, NativeError e, string message) : base(message)
        {
            Status = status; Kind = e.Kind; Operand = e.Operand; Index = e.Index; Vertex = e.Vertex;
            Value = e.Value; Limit = e.Limit; Minimum = e.Minimum; Where = e.Where;
        }

        internal static void Check(int status, ref NativeError e)
        {
            EdgelandException error = Failure(status, ref e);
            if (error != null) throw error;
        }

        // The exception of a status and its error, not thrown; null for EL_OK.
        internal static unsafe EdgelandException Failure(int status, ref NativeError e)
        {
            if (status == 0) return null;
            string message;
            fixed (byte* m = e.Message)
            {
                int n = 0;
                while (n < 256 && m[n] != 0) ++n;
                message = Encoding.UTF8.GetString(m, n);
            }
            return Make(status, e, message);
        }

        static EdgelandException Make(int status, NativeError e, string message)
        {
            switch (status)
            {
                case 1: return new NullArgumentException(status, e, message);
                case 2: return new MemoryExhaustedException(status, e, message);
                case 3: return new VersionMismatchException(status, e, message);
                case 4: return new InternalErrorException(status, e, message);
                case 10: return new InvalidInputException(status, e, message);
                case 11: return new CoordinateOutOfRangeException(status, e, message);
                case 12: return new InvalidBoxException(status, e, message);
                case 13: return new TooManyVerticesException(status, e, message);
                case 14: return new InvalidArgumentException(status, e, message);
                case 15: return new ArgumentRangeException(status, e, message);
                case 16: return new NonPositiveAreaException(status, e, message);
                case 17: return new InvalidOverlayException(status, e, message);
                case 20: return new InvalidConfigException(status, e, message);
                case 21: return new InvalidMaterialException(status, e, message);
                case 22: return new LimitExceededException(status, e, message);
                case 23: return new LoadException(status, e, message);
                case 24: return new DeltaException(status, e, message);
                case 25: return new DeltaMismatchException(status, e, message);
                case 26: return new InvalidPathException(status, e, message);
                case 27: return new RegionNotLoadedException(status, e, message);
                case 28: return new UnknownPolygonException(status, e, message);
                case 30: return new StaleIslandException(status, e, message);
                case 40: return new IndexRangeException(status, e, message);
                case 41: return new BufferTooSmallException(status, e, message);
                default: return new EdgelandException(status, e, message);
            }
        }
    }

    // EL_NULL_ARGUMENT: a disposed object was used.
    public class NullArgumentException : EdgelandException { internal NullArgumentException(int s, NativeError e, string m) : base(s, e, m) { } }
    // EL_OUT_OF_MEMORY [std::bad_alloc].
    public class MemoryExhaustedException : EdgelandException { internal MemoryExhaustedException(int s, NativeError e, string m) : base(s, e, m) { } }
    // EL_VERSION_MISMATCH.
    public class VersionMismatchException : EdgelandException { internal VersionMismatchException(int s, NativeError e, string m) : base(s, e, m) { } }
    // EL_INTERNAL: a bug in edgeland [LandscapeInternalError, InternalError].
    public class InternalErrorException : EdgelandException { internal InternalErrorException(int s, NativeError e, string m) : base(s, e, m) { } }
    // EL_INVALID_INPUT: a shape breaks a rule of validate(); Kind is the rule [InvalidInput].
    public class InvalidInputException : EdgelandException { internal InvalidInputException(int s, NativeError e, string m) : base(s, e, m) { } }
    // EL_COORDINATE_OUT_OF_RANGE [CoordinateOutOfRange].
    public class CoordinateOutOfRangeException : InvalidInputException { internal CoordinateOutOfRangeException(int s, NativeError e, string m) : base(s, e, m) { } }
    // EL_INVALID_BOX [InvalidBox].
    public class InvalidBoxException : InvalidInputException { internal InvalidBoxException(int s, NativeError e, string m) : base(s, e, m) { } }
    // EL_TOO_MANY_VERTICES [TooManyVertices].
    public class TooManyVerticesException : EdgelandException { internal TooManyVerticesException(int s, NativeError e, string m) : base(s, e, m) { } }
    // EL_INVALID_ARGUMENT [InvalidArgument].
    public class InvalidArgumentException : EdgelandException { internal InvalidArgumentException(int s, NativeError e, string m) : base(s, e, m) { } }
    // EL_ARGUMENT_OUT_OF_RANGE [ArgumentOutOfRange].
    public class ArgumentRangeException : EdgelandException { internal ArgumentRangeException(int s, NativeError e, string m) : base(s, e, m) { } }
    // EL_NON_POSITIVE_AREA [NonPositiveArea].
    public class NonPositiveAreaException : EdgelandException { internal NonPositiveAreaException(int s, NativeError e, string m) : base(s, e, m) { } }
    // EL_INVALID_OVERLAY [InvalidOverlay].
    public class InvalidOverlayException : EdgelandException { internal InvalidOverlayException(int s, NativeError e, string m) : base(s, e, m) { } }
    // EL_INVALID_CONFIG: Kind is the setting [InvalidConfig].
    public class InvalidConfigException : EdgelandException { internal InvalidConfigException(int s, NativeError e, string m) : base(s, e, m) { } }
    // EL_INVALID_MATERIAL: Value is the number given [InvalidMaterial].
    public class InvalidMaterialException : EdgelandException { internal InvalidMaterialException(int s, NativeError e, string m) : base(s, e, m) { } }
    // EL_LIMIT_EXCEEDED: Kind is the limit, Value requested of at most Limit [LimitExceeded].
    public class LimitExceededException : EdgelandException { internal LimitExceededException(int s, NativeError e, string m) : base(s, e, m) { } }
    // EL_LOAD_ERROR: Index is the byte offset [LoadError]; or the line (1-based) a replayed edit
    // log stopped at (Landscape.ReplayLog).
    public class LoadException : EdgelandException { internal LoadException(int s, NativeError e, string m) : base(s, e, m) { } }
    // EL_DELTA_ERROR: Index is the byte offset [DeltaError].
    public class DeltaException : EdgelandException { internal DeltaException(int s, NativeError e, string m) : base(s, e, m) { } }
    // EL_DELTA_MISMATCH: Kind is the field that differs [DeltaMismatch].
    public class DeltaMismatchException : EdgelandException { internal DeltaMismatchException(int s, NativeError e, string m) : base(s, e, m) { } }
    // EL_INVALID_PATH: Index is the path's length [InvalidPath].
    public class InvalidPathException : EdgelandException { internal InvalidPathException(int s, NativeError e, string m) : base(s, e, m) { } }
    // EL_REGION_NOT_LOADED: Index is the region path's length [RegionNotLoaded].
    public class RegionNotLoadedException : EdgelandException { internal RegionNotLoadedException(int s, NativeError e, string m) : base(s, e, m) { } }
    // EL_UNKNOWN_POLYGON: Index is the polygon id [UnknownPolygon].
    public class UnknownPolygonException : EdgelandException { internal UnknownPolygonException(int s, NativeError e, string m) : base(s, e, m) { } }
    // EL_STALE_ISLAND: Index is the polygon id [StaleIsland].
    public class StaleIslandException : EdgelandException { internal StaleIslandException(int s, NativeError e, string m) : base(s, e, m) { } }
    // EL_INDEX_OUT_OF_RANGE.
    public class IndexRangeException : EdgelandException { internal IndexRangeException(int s, NativeError e, string m) : base(s, e, m) { } }
    // EL_BUFFER_TOO_SMALL.
    public class BufferTooSmallException : EdgelandException { internal BufferTooSmallException(int s, NativeError e, string m) : base(s, e, m) { } }
}
