// The landscape, shapes and results for C#: the C API's surface with .NET names, exceptions for
// statuses, IDisposable objects over SafeHandles (bindings/csharp/README.md).
using System;
using System.Collections.Generic;
using System.Numerics;
using System.Runtime.InteropServices;
using System.Text;

namespace Edgeland
{
    // One landscape polygon: id, material, its cell's box, its points (counter-clockwise).
    public sealed class Polygon
    {
        public ulong Id;
        public byte Material;
        public Box Cell;
        public Point[] Points;
    }

    // What an edit changed: ids removed (ascending), polygons added (ascending id), the cells
    // rebuilt, twice the change of area per material (exact; sums to zero). It keeps the C change
    // set, which the game layer's trackers and MeshUpdate take: Dispose() frees it at once.
    public sealed class ChangeSet : IDisposable
    {
        public ulong[] Removed;
        public Polygon[] Added;
        public Box[] Cells;
        public Dictionary<int, BigInteger> AreaDelta;
        internal SafeHandle Owner;   // the handle that owns the C change set
        internal IntPtr Pointer;     // the C change set (borrowed from Owner for detach's)

        // The C change set for a call; the owner stays alive (and checked) through it.
        internal IntPtr Use()
        {
            if (Owner.IsClosed) throw new ObjectDisposedException("ChangeSet");
            return Pointer;
        }

        public void Dispose() { Owner.Dispose(); }
    }

    // A polygon set validated once (strictly simple, counter-clockwise, disjoint interiors).
    public sealed class Shape : IDisposable
    {
        internal ShapeHandle Handle;

        Shape(ShapeHandle handle) { Handle = handle; }

        // From polygons, each an array of points. InvalidInputException names the polygon and
        // vertex of a broken rule, CoordinateOutOfRangeException a coordinate beyond 2^31 - 1.
        public Shape(params Point[][] polygons)
        {
            var offsets = new uint[polygons.Length + 1];
            var xy = new List<long>();
            for (int i = 0; i < polygons.Length; ++i)
            {
                foreach (Point p in polygons[i]) { xy.Add(p.X); xy.Add(p.Y); }
                offsets[i + 1] = (uint)(xy.Count / 2);
            }
            var e = Call.Error();
            EdgelandException.Check(Native.el_shape_create(xy.ToArray(), offsets, (UIntPtr)polygons.Length, out Handle, ref e), ref e);
        }

        // Any polygons read with OGC semantics (el_shape_import; JavaScript's Shape.import): each
        // polygon its rings, the exterior then its holes, as another library or an editor drew
        // them: clockwise, self-intersecting or touching. Each ring winds around its points
        // (non-zero), exteriors +1, holes -1; the shape is where the sum is positive, as valid
        // hole-free pieces (none for rings of no area). CoordinateOutOfRangeException names the
        // polygon (Index) and the vertex in its ring.
        public static Shape Import(params Point[][][] polygons)
        {
            var polygonRings = new uint[polygons.Length + 1];
            var ringOffsets = new List<uint> { 0 };
            var xy = new List<long>();
            for (int i = 0; i < polygons.Length; ++i)
            {
                foreach (Point[] ring in polygons[i])
                {
                    foreach (Point p in ring) { xy.Add(p.X); xy.Add(p.Y); }
                    ringOffsets.Add((uint)(xy.Count / 2));
                }
                polygonRings[i + 1] = (uint)(ringOffsets.Count - 1);
            }
            var e = Call.Error();
            ShapeHandle h;
            EdgelandException.Check(Native.el_shape_import(xy.ToArray(), ringOffsets.ToArray(), polygonRings, (UIntPtr)polygons.Length, out h, ref e), ref e);
            return new Shape(h);
        }

        public static Shape Circle(Point center, long radius)
        {
            var e = Call.Error();
            ShapeHandle h;
            EdgelandException.Check(Native.el_shape_circle(ref center, radius, out h, ref e), ref e);
            return new Shape(h);
        }

        public static Shape RegularPolygon(Point center, long radius, long sides, long phaseNum = 0, long phaseDen = 1)
        {
            var e = Call.Error();
            ShapeHandle h;
            EdgelandException.Check(Native.el_shape_regular_polygon(ref center, radius, sides, phaseNum, phaseDen, out h, ref e), ref e);
            return new Shape(h);
        }

        public static Shape Capsule(Point a, Point b, long radius)
        {
            var e = Call.Error();
            ShapeHandle h;
            EdgelandException.Check(Native.el_shape_capsule(ref a, ref b, radius, out h, ref e), ref e);
            return new Shape(h);
        }

        public static Shape Rectangle(Box box)
        {
            var e = Call.Error();
            ShapeHandle h;
            EdgelandException.Check(Native.el_shape_box(ref box, out h, ref e), ref e);
            return new Shape(h);
        }

        public static Shape RotatedBox(Point center, long halfWidth, long halfHeight, long angleNum, long angleDen)
        {
            var e = Call.Error();
            ShapeHandle h;
            EdgelandException.Check(Native.el_shape_rotated_box(ref center, halfWidth, halfHeight, angleNum, angleDen, out h, ref e), ref e);
            return new Shape(h);
        }

        public Point[][] Polygons
        {
            get
            {
                var e = Call.Error();
                PolygonsHandle h;
                EdgelandException.Check(Native.el_shape_polygons(Handle, out h, ref e), ref e);
                using (h)
                {
                    Polygon[] all = Results.Polygons(h.DangerousGetHandle());
                    var out_ = new Point[all.Length][];
                    for (int i = 0; i < all.Length; ++i) out_[i] = all[i].Points;
                    return out_;
                }
            }
        }

        public void Dispose() { Handle.Dispose(); }
    }

    public sealed class Landscape : IDisposable
    {
        LandscapeHandle handle;
        internal LandscapeHandle Raw { get { return handle; } }

        Landscape(LandscapeHandle h) { handle = h; }
        internal static Landscape Own(LandscapeHandle h) { return new Landscape(h); }

        // The library's defaults (edge cap 64, ...), to change before passing to the constructor.
        public static LandscapeConfig DefaultConfig()
        {
            var c = new LandscapeConfig();
            Native.el_landscape_config_init(ref c);
            return c;
        }

        // A world over the box, empty (material 0) or filled with `fill`.
        public Landscape(Box world, int fill = 0) : this(world, fill, DefaultConfig()) { }

        public Landscape(Box world, int fill, LandscapeConfig config)
        {
            var e = Call.Error();
            EdgelandException.Check(Native.el_landscape_create(ref world, fill, ref config, out handle, ref e), ref e);
        }

        // A snapshot in O(1): later edits of either never show in the other.
        public Landscape Clone()
        {
            var e = Call.Error();
            LandscapeHandle h;
            EdgelandException.Check(Native.el_landscape_clone(handle, out h, ref e), ref e);
            return new Landscape(h);
        }

        public void Dispose() { handle.Dispose(); }

        // --- edits: a failed one throws and leaves the world as it was ---
        public ChangeSet Carve(Shape shape)
        {
            var e = Call.Error();
            ChangesHandle h;
            EdgelandException.Check(Native.el_landscape_carve(handle, shape.Handle, out h, ref e), ref e);
            return Results.Changes(h);
        }

        public ChangeSet Fill(Shape shape, int material)
        {
            var e = Call.Error();
            ChangesHandle h;
            EdgelandException.Check(Native.el_landscape_fill(handle, shape.Handle, material, out h, ref e), ref e);
            return Results.Changes(h);
        }

        public ChangeSet FillEmpty(Shape shape, int material)
        {
            var e = Call.Error();
            ChangesHandle h;
            EdgelandException.Check(Native.el_landscape_fill_empty(handle, shape.Handle, material, out h, ref e), ref e);
            return Results.Changes(h);
        }

        public ChangeSet Replace(Shape shape, int from, int to)
        {
            var e = Call.Error();
            ChangesHandle h;
            EdgelandException.Check(Native.el_landscape_replace(handle, shape.Handle, from, to, out h, ref e), ref e);
            return Results.Changes(h);
        }

        // Under the shape every material m of the pairs becomes its partner, all at once.
        public ChangeSet Relabel(Shape shape, params KeyValuePair<int, int>[] pairs)
        {
            var fromTo = new int[2 * pairs.Length];
            for (int i = 0; i < pairs.Length; ++i) { fromTo[2 * i] = pairs[i].Key; fromTo[2 * i + 1] = pairs[i].Value; }
            var e = Call.Error();
            ChangesHandle h;
            EdgelandException.Check(Native.el_landscape_relabel(handle, shape.Handle, fromTo, (UIntPtr)pairs.Length, out h, ref e), ref e);
            return Results.Changes(h);
        }

        // --- queries ---
        public byte MaterialAt(Point p)
        {
            var e = Call.Error();
            byte m;
            EdgelandException.Check(Native.el_landscape_material_at(handle, ref p, out m, ref e), ref e);
            return m;
        }

        public Crossing[] Crossings(Point from, Point to)
        {
            var e = Call.Error();
            CrossingsHandle h;
            EdgelandException.Check(Native.el_landscape_crossings(handle, ref from, ref to, out h, ref e), ref e);
            using (h)
            {
                UIntPtr needed;
                Native.el_crossings_copy(h, null, UIntPtr.Zero, out needed);
                var all = new Crossing[(int)needed];
                Native.el_crossings_copy(h, all, needed, out needed);
                return all;
            }
        }

        public Crossing? Raycast(Point from, Point to)
        {
            var e = Call.Error();
            int hit;
            Crossing c;
            EdgelandException.Check(Native.el_landscape_raycast(handle, ref from, ref to, out hit, out c, ref e), ref e);
            return hit != 0 ? c : (Crossing?)null;
        }

        public byte[] Overlaps(Box box)
        {
            var e = Call.Error();
            var materials = new byte[256];
            UIntPtr n;
            EdgelandException.Check(Native.el_landscape_overlaps_box(handle, ref box, materials, out n, ref e), ref e);
            Array.Resize(ref materials, (int)n);
            return materials;
        }

        public byte[] Overlaps(Shape shape)
        {
            var e = Call.Error();
            var materials = new byte[256];
            UIntPtr n;
            EdgelandException.Check(Native.el_landscape_overlaps_shape(handle, shape.Handle, materials, out n, ref e), ref e);
            Array.Resize(ref materials, (int)n);
            return materials;
        }

        public Polygon[] PolygonsIn(Box box)
        {
            var e = Call.Error();
            PolygonsHandle h;
            EdgelandException.Check(Native.el_landscape_polygons_in(handle, ref box, out h, ref e), ref e);
            using (h) return Results.Polygons(h.DangerousGetHandle());
        }

        // The boxes of the cells (the tree's leaves, empty ones too) that meet the closed box, in
        // tree order; CellsIn() every cell of the world.
        public Box[] CellsIn(Box box)
        {
            var e = Call.Error();
            var cells = new Box[(int)Stats.Cells];  // every cell of the world: enough for any box
            UIntPtr n;
            EdgelandException.Check(Native.el_landscape_cells_in(handle, ref box, cells, (UIntPtr)cells.Length, out n, ref e), ref e);
            Array.Resize(ref cells, (int)n);
            return cells;
        }

        public Box[] CellsIn() { return CellsIn(World); }

        public BigInteger TwiceArea(int material)
        {
            var e = Call.Error();
            Int128Value v;
            EdgelandException.Check(Native.el_landscape_twice_area(handle, material, out v, ref e), ref e);
            return v.ToBigInteger();
        }

        public Box World
        {
            get
            {
                var e = Call.Error();
                Box b;
                EdgelandException.Check(Native.el_landscape_world(handle, out b, ref e), ref e);
                return b;
            }
        }

        public LandscapeStats Stats
        {
            get
            {
                var e = Call.Error();
                var s = new LandscapeStats();
                Native.el_stats_init(ref s);
                EdgelandException.Check(Native.el_landscape_stats(handle, ref s, ref e), ref e);
                return s;
            }
        }

        // The 64-bit state hash: equal states, equal hashes, on every platform.
        public ulong StateHash
        {
            get
            {
                var e = Call.Error();
                ulong h;
                EdgelandException.Check(Native.el_landscape_state_hash(handle, out h, ref e), ref e);
                return h;
            }
        }

        // Every invariant over the whole world: the problems found (none: valid).
        public string[] Check()
        {
            var e = Call.Error();
            BytesHandle h;
            EdgelandException.Check(Native.el_landscape_check(handle, out h, ref e), ref e);
            string text = Encoding.UTF8.GetString(Results.Bytes(h));
            return text.Length == 0 ? new string[0] : text.TrimEnd('\n').Split('\n');
        }

        public bool Checked
        {
            set
            {
                var e = Call.Error();
                EdgelandException.Check(Native.el_landscape_set_checked(handle, value ? 1 : 0, ref e), ref e);
            }
        }

        public void StartLog()
        {
            var e = Call.Error();
            EdgelandException.Check(Native.el_landscape_start_log(handle, ref e), ref e);
        }

        public void StopLog()
        {
            var e = Call.Error();
            EdgelandException.Check(Native.el_landscape_stop_log(handle, ref e), ref e);
        }

        public string Log
        {
            get
            {
                var e = Call.Error();
                BytesHandle h;
                EdgelandException.Check(Native.el_landscape_log(handle, out h, ref e), ref e);
                return Encoding.UTF8.GetString(Results.Bytes(h));
            }
        }

        // The versioned, checksummed binary save.
        public byte[] Save()
        {
            var e = Call.Error();
            BytesHandle h;
            EdgelandException.Check(Native.el_landscape_save(handle, out h, ref e), ref e);
            return Results.Bytes(h);
        }

        // A world from save bytes (untrusted: LoadException's Index is the byte offset).
        public static Landscape Load(byte[] data)
        {
            var e = Call.Error();
            var c = DefaultConfig();
            LandscapeHandle h;
            EdgelandException.Check(Native.el_landscape_load(data, (UIntPtr)data.Length, ref c, out h, ref e), ref e);
            return new Landscape(h);
        }

        // Replays an edit log (Log's text) as `edgeland replay` does: the world of its world line,
        // then its edits in order up to the first bad line or refused edit (Replay.cs).
        public static Replay ReplayLog(string log) { return Replay.Of(log); }

        public static uint Version { get { return Native.el_version(); } }
    }

    internal static class Call
    {
        static Call()
        {
            Layout.Check();
            if (Native.el_check_version(0x010000) != 0)
                throw new InvalidOperationException("libedgeland_c " + Native.el_version().ToString("x6") + " does not serve this binding (1.0)");
        }

        public static NativeError Error()
        {
            var e = new NativeError();
            Native.el_error_init(ref e);
            return e;
        }
    }

    internal static unsafe class Results
    {
        public static Polygon[] Polygons(IntPtr h)
        {
            UIntPtr n;
            int count = (int)Native.el_polygons_count(h);
            ulong* ids = (ulong*)Native.el_polygons_ids(h, out n);
            byte* materials = (byte*)Native.el_polygons_materials(h, out n);
            Box* cells = (Box*)Native.el_polygons_cells(h, out n);
            uint* offsets = (uint*)Native.el_polygons_offsets(h, out n);
            Point* points = (Point*)Native.el_polygons_points(h, out n);
            var out_ = new Polygon[count];
            for (int i = 0; i < count; ++i)
            {
                var ring = new Point[offsets[i + 1] - offsets[i]];
                for (int k = 0; k < ring.Length; ++k) ring[k] = points[offsets[i] + k];
                out_[i] = new Polygon { Id = ids[i], Material = materials[i], Cell = cells[i], Points = ring };
            }
            return out_;
        }

        public static ChangeSet Changes(ChangesHandle h)
        {
            return Changes(h, h.DangerousGetHandle());
        }

        // The change set behind `pointer`, kept alive by `owner`.
        public static ChangeSet Changes(SafeHandle owner, IntPtr pointer)
        {
            UIntPtr n;
            ulong* removed = (ulong*)Native.el_changes_removed(pointer, out n);
            var r = new ulong[(int)n];
            for (int i = 0; i < r.Length; ++i) r[i] = removed[i];
            Box* cells = (Box*)Native.el_changes_cells(pointer, out n);
            var c = new Box[(int)n];
            for (int i = 0; i < c.Length; ++i) c[i] = cells[i];
            AreaDelta* deltas = (AreaDelta*)Native.el_changes_area_delta(pointer, out n);
            var d = new Dictionary<int, BigInteger>();
            for (int i = 0; i < (int)n; ++i) d[(int)deltas[i].Material] = deltas[i].TwiceArea.ToBigInteger();
            return new ChangeSet { Removed = r, Added = Polygons(Native.el_changes_added(pointer)), Cells = c, AreaDelta = d, Owner = owner, Pointer = pointer };
        }

        public static byte[] Bytes(BytesHandle h)
        {
            using (h)
            {
                UIntPtr needed;
                Native.el_bytes_copy(h, null, UIntPtr.Zero, out needed);
                var data = new byte[(int)needed];
                if (data.Length > 0) Native.el_bytes_copy(h, data, needed, out needed);
                return data;
            }
        }
    }
}
