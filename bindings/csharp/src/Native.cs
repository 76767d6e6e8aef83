// The C API (capi/include/edgeland/edgeland.h) as P/Invoke declarations: blittable structs laid
// out as the header's (its EL_LAYOUT_ASSERTs; Layout.Check compares), SafeHandles that call the
// matching el_*_destroy. Internal: the public surface is Landscape, Shape and their results.
using System;
using System.Runtime.InteropServices;

namespace Edgeland
{
    [StructLayout(LayoutKind.Sequential)]
    public struct Point
    {
        public long X, Y;
        public Point(long x, long y) { X = x; Y = y; }
        public override string ToString() { return "(" + X + " " + Y + ")"; }
    }

    [StructLayout(LayoutKind.Sequential)]
    public struct Box
    {
        public Point Min, Max;
        public Box(long x0, long y0, long x1, long y1) { Min = new Point(x0, y0); Max = new Point(x1, y1); }
    }

    // An exact 128-bit value: Hi * 2^64 + Lo (two's complement) and the nearest double.
    [StructLayout(LayoutKind.Sequential)]
    public struct Int128Value
    {
        public ulong Lo;
        public long Hi;
        public double Approx;
        public System.Numerics.BigInteger ToBigInteger()
        {
            return (new System.Numerics.BigInteger(Hi) << 64) + new System.Numerics.BigInteger(Lo);
        }
    }

    // A material change along a segment (C++ MaterialCrossing): t = TNum / TDen along it, the
    // point (XNum / Den, YNum / Den), its rounding, the polygon entered (After != 0) or left and
    // its edge, the edge's outward normal (not normalised).
    [StructLayout(LayoutKind.Sequential)]
    public struct Crossing
    {
        public Int128Value TNum, TDen, XNum, YNum, Den;
        public Point Rounded, Normal;
        public ulong Polygon;
        public uint Edge;
        public byte Before, After;
        byte reserved0, reserved1;
    }

    [StructLayout(LayoutKind.Sequential)]
    public struct AreaDelta
    {
        public Int128Value TwiceArea;
        public uint Material;
        uint reserved;
    }

    // One surface chain beside its points (el_chain_info).
    [StructLayout(LayoutKind.Sequential)]
    public struct ChainInfo
    {
        public Box Cell;
        public Point GhostPrev, GhostNext;
        public ulong Id;
        public uint Closed;
        uint reserved;
    }

    [StructLayout(LayoutKind.Sequential)]
    internal struct IslandInfo
    {
        public Box Bounds;
        public Int128Value TwiceArea;
        public uint FirstPiece, PieceCount;
    }

    [StructLayout(LayoutKind.Sequential)]
    internal struct DetachedInfo
    {
        public Int128Value TwiceArea, CentroidXNum, CentroidYNum, CentroidDen;
    }

    // Which materials collide and which never fall (el_physics_materials).
    [StructLayout(LayoutKind.Sequential)]
    internal unsafe struct NativePhysicsMaterials
    {
        public uint StructSize;
        public uint Flags;
        public fixed byte Solid[256];
        public fixed byte Anchored[256];
    }

    // C++ GameOptions (el_game_options); GameOptions is the public side.
    [StructLayout(LayoutKind.Sequential)]
    internal unsafe struct NativeGameOptions
    {
        public uint StructSize;
        public uint Flags;  // 1 meshes, 2 debris, 4 border wall
        public ulong DebrisBudget;
        public uint MaxPieceVertices, MaxDebrisWait;
        public fixed byte Solid[256];
        public fixed byte Anchored[256];
    }

    // One debris body (el_debris_info): runs of the update's regions and pieces.
    [StructLayout(LayoutKind.Sequential)]
    internal struct DebrisInfo
    {
        public Box Bounds;
        public Int128Value TwiceArea, CentroidXNum, CentroidYNum, CentroidDen;
        public uint FirstRegion, RegionCount, FirstPiece, PieceCount;
    }

    // What one update did (C++ GameWork) and the islands still waiting (el_game_work).
    [StructLayout(LayoutKind.Sequential)]
    public struct GameWork
    {
        public uint StructSize;
        uint reserved;
        public ulong CellsScanned, BoundaryPasses, CellsTraced, IslandsFound, IslandsDetached, DebrisWaiting;
    }

    [StructLayout(LayoutKind.Sequential)]
    internal unsafe struct NativeError
    {
        public uint StructSize;
        public int Status;
        public uint Kind, Operand;
        public ulong Index, Vertex;
        public long Value, Limit, Minimum;
        public Point Where;
        public fixed byte Message[256];
    }

    // C++ LandscapeConfig and LandscapeLimits; Landscape.DefaultConfig() has the library's defaults.
    [StructLayout(LayoutKind.Sequential)]
    public struct LandscapeConfig
    {
        public uint StructSize;
        public uint Tree;  // 0 quadtree, 1 kd-tree
        public uint EdgeCap, MergeBelow;
        public long MinCellSize;
        public int GridDepth;  // -1: adaptive
        public uint Flags;     // 1: checked (every edit re-verifies every invariant)
        public ulong MaxVertices, MaxShapeVertices, MaxCells;
    }

    [StructLayout(LayoutKind.Sequential)]
    public struct LandscapeStats
    {
        public uint StructSize;
        uint reserved;
        public ulong Polygons, Vertices, Cells, Depth, Bytes;
    }

    internal abstract class NativeHandle : SafeHandle
    {
        protected NativeHandle() : base(IntPtr.Zero, true) { }
        public override bool IsInvalid { get { return handle == IntPtr.Zero; } }
    }
    internal sealed class LandscapeHandle : NativeHandle
    {
        protected override bool ReleaseHandle() { Native.el_landscape_destroy(handle); return true; }
    }
    internal sealed class ShapeHandle : NativeHandle
    {
        protected override bool ReleaseHandle() { Native.el_shape_destroy(handle); return true; }
    }
    internal sealed class ChangesHandle : NativeHandle
    {
        protected override bool ReleaseHandle() { Native.el_changes_destroy(handle); return true; }
    }
    internal sealed class PolygonsHandle : NativeHandle
    {
        protected override bool ReleaseHandle() { Native.el_polygons_destroy(handle); return true; }
    }
    internal sealed class CrossingsHandle : NativeHandle
    {
        protected override bool ReleaseHandle() { Native.el_crossings_destroy(handle); return true; }
    }
    internal sealed class BytesHandle : NativeHandle
    {
        protected override bool ReleaseHandle() { Native.el_bytes_destroy(handle); return true; }
    }

    internal sealed class ReplayHandle : NativeHandle
    {
        protected override bool ReleaseHandle() { Native.el_replay_destroy(handle); return true; }
    }

    internal sealed class SurfaceTrackerHandle : NativeHandle
    {
        protected override bool ReleaseHandle() { Native.el_surface_tracker_destroy(handle); return true; }
    }
    internal sealed class IslandTrackerHandle : NativeHandle
    {
        protected override bool ReleaseHandle() { Native.el_island_tracker_destroy(handle); return true; }
    }
    internal sealed class ChainsHandle : NativeHandle
    {
        protected override bool ReleaseHandle() { Native.el_chains_destroy(handle); return true; }
    }
    internal sealed class IslandsHandle : NativeHandle
    {
        protected override bool ReleaseHandle() { Native.el_islands_destroy(handle); return true; }
    }
    internal sealed class DetachedHandle : NativeHandle
    {
        protected override bool ReleaseHandle() { Native.el_detached_destroy(handle); return true; }
    }
    internal sealed class MeshesHandle : NativeHandle
    {
        protected override bool ReleaseHandle() { Native.el_meshes_destroy(handle); return true; }
    }

    internal sealed class EditsHandle : NativeHandle
    {
        protected override bool ReleaseHandle() { Native.el_edits_destroy(handle); return true; }
    }
    internal sealed class GameDriverHandle : NativeHandle
    {
        protected override bool ReleaseHandle() { Native.el_game_driver_destroy(handle); return true; }
    }
    internal sealed class GameUpdateHandle : NativeHandle
    {
        protected override bool ReleaseHandle() { Native.el_game_update_destroy(handle); return true; }
    }

    internal static class Native
    {
        // libedgeland_c.so / edgeland_c.dll / libedgeland_c.dylib; on iOS (static library)
        // this would be "__Internal" (untested: bindings/csharp/README.md).
        const string Lib = "edgeland_c";

        [DllImport(Lib)] public static extern uint el_version();
        [DllImport(Lib)] public static extern int el_check_version(uint headerVersion);
        [DllImport(Lib)] public static extern void el_error_init(ref NativeError error);

        [DllImport(Lib)] public static extern int el_shape_create(long[] xy, uint[] offsets, UIntPtr count, out ShapeHandle shape, ref NativeError error);
        [DllImport(Lib)] public static extern int el_shape_circle(ref Point center, long radius, out ShapeHandle shape, ref NativeError error);
        [DllImport(Lib)] public static extern int el_shape_regular_polygon(ref Point center, long radius, long sides, long phaseNum, long phaseDen, out ShapeHandle shape, ref NativeError error);
        [DllImport(Lib)] public static extern int el_shape_capsule(ref Point a, ref Point b, long radius, out ShapeHandle shape, ref NativeError error);
        [DllImport(Lib)] public static extern int el_shape_box(ref Box box, out ShapeHandle shape, ref NativeError error);
        [DllImport(Lib)] public static extern int el_shape_rotated_box(ref Point center, long halfWidth, long halfHeight, long angleNum, long angleDen, out ShapeHandle shape, ref NativeError error);
        [DllImport(Lib)] public static extern int el_shape_import(long[] xy, uint[] ringOffsets, uint[] polygonRings, UIntPtr count, out ShapeHandle shape, ref NativeError error);
        [DllImport(Lib)] public static extern int el_shape_polygons(ShapeHandle shape, out PolygonsHandle polygons, ref NativeError error);
        [DllImport(Lib)] public static extern void el_shape_destroy(IntPtr shape);

        [DllImport(Lib)] public static extern void el_landscape_config_init(ref LandscapeConfig config);
        [DllImport(Lib)] public static extern int el_landscape_create(ref Box world, int fill, ref LandscapeConfig config, out LandscapeHandle landscape, ref NativeError error);
        [DllImport(Lib)] public static extern int el_landscape_clone(LandscapeHandle landscape, out LandscapeHandle copy, ref NativeError error);
        [DllImport(Lib)] public static extern void el_landscape_destroy(IntPtr landscape);
        [DllImport(Lib)] public static extern int el_landscape_carve(LandscapeHandle landscape, ShapeHandle shape, out ChangesHandle changes, ref NativeError error);
        [DllImport(Lib)] public static extern int el_landscape_fill(LandscapeHandle landscape, ShapeHandle shape, int material, out ChangesHandle changes, ref NativeError error);
        [DllImport(Lib)] public static extern int el_landscape_fill_empty(LandscapeHandle landscape, ShapeHandle shape, int material, out ChangesHandle changes, ref NativeError error);
        [DllImport(Lib)] public static extern int el_landscape_replace(LandscapeHandle landscape, ShapeHandle shape, int from, int to, out ChangesHandle changes, ref NativeError error);
        [DllImport(Lib)] public static extern int el_landscape_relabel(LandscapeHandle landscape, ShapeHandle shape, int[] fromTo, UIntPtr pairs, out ChangesHandle changes, ref NativeError error);
        [DllImport(Lib)] public static extern int el_landscape_material_at(LandscapeHandle landscape, ref Point p, out byte material, ref NativeError error);
        [DllImport(Lib)] public static extern int el_landscape_crossings(LandscapeHandle landscape, ref Point from, ref Point to, out CrossingsHandle crossings, ref NativeError error);
        [DllImport(Lib)] public static extern int el_landscape_raycast(LandscapeHandle landscape, ref Point from, ref Point to, out int hit, out Crossing crossing, ref NativeError error);
        [DllImport(Lib)] public static extern int el_landscape_overlaps_box(LandscapeHandle landscape, ref Box box, byte[] materials, out UIntPtr count, ref NativeError error);
        [DllImport(Lib)] public static extern int el_landscape_overlaps_shape(LandscapeHandle landscape, ShapeHandle shape, byte[] materials, out UIntPtr count, ref NativeError error);
        [DllImport(Lib)] public static extern int el_landscape_polygons_in(LandscapeHandle landscape, ref Box box, out PolygonsHandle polygons, ref NativeError error);
        [DllImport(Lib)] public static extern int el_landscape_cells_in(LandscapeHandle landscape, ref Box box, [Out] Box[] buf, UIntPtr cap, out UIntPtr needed, ref NativeError error);
        [DllImport(Lib)] public static extern int el_landscape_twice_area(LandscapeHandle landscape, int material, out Int128Value area, ref NativeError error);
        [DllImport(Lib)] public static extern int el_landscape_world(LandscapeHandle landscape, out Box world, ref NativeError error);
        [DllImport(Lib)] public static extern void el_stats_init(ref LandscapeStats stats);
        [DllImport(Lib)] public static extern int el_landscape_stats(LandscapeHandle landscape, ref LandscapeStats stats, ref NativeError error);
        [DllImport(Lib)] public static extern int el_landscape_state_hash(LandscapeHandle landscape, out ulong hash, ref NativeError error);
        [DllImport(Lib)] public static extern int el_landscape_check(LandscapeHandle landscape, out BytesHandle problems, ref NativeError error);
        [DllImport(Lib)] public static extern int el_landscape_set_checked(LandscapeHandle landscape, int on, ref NativeError error);
        [DllImport(Lib)] public static extern int el_landscape_start_log(LandscapeHandle landscape, ref NativeError error);
        [DllImport(Lib)] public static extern int el_landscape_stop_log(LandscapeHandle landscape, ref NativeError error);
        [DllImport(Lib)] public static extern int el_landscape_log(LandscapeHandle landscape, out BytesHandle log, ref NativeError error);
        [DllImport(Lib)] public static extern int el_landscape_save(LandscapeHandle landscape, out BytesHandle bytes, ref NativeError error);
        [DllImport(Lib)] public static extern int el_landscape_load(byte[] data, UIntPtr size, ref LandscapeConfig config, out LandscapeHandle landscape, ref NativeError error);

        [DllImport(Lib)] public static extern int el_replay_log(byte[] text, UIntPtr size, out ReplayHandle replay, ref NativeError error);
        [DllImport(Lib)] public static extern void el_replay_destroy(IntPtr replay);
        [DllImport(Lib)] public static extern int el_replay_landscape(ReplayHandle replay, out LandscapeHandle landscape, ref NativeError error);
        [DllImport(Lib)] public static extern UIntPtr el_replay_edits(ReplayHandle replay);
        [DllImport(Lib)] public static extern int el_replay_stopped(ReplayHandle replay, ref NativeError error);
        [DllImport(Lib)] public static extern int el_replay_report(ReplayHandle replay, out BytesHandle report, ref NativeError error);

        [DllImport(Lib)] public static extern void el_changes_destroy(IntPtr changes);
        [DllImport(Lib)] public static extern IntPtr el_changes_removed(IntPtr changes, out UIntPtr count);
        [DllImport(Lib)] public static extern IntPtr el_changes_added(IntPtr changes);
        [DllImport(Lib)] public static extern IntPtr el_changes_cells(IntPtr changes, out UIntPtr count);
        [DllImport(Lib)] public static extern IntPtr el_changes_area_delta(IntPtr changes, out UIntPtr count);

        [DllImport(Lib)] public static extern void el_polygons_destroy(IntPtr polygons);
        [DllImport(Lib)] public static extern UIntPtr el_polygons_count(IntPtr polygons);
        [DllImport(Lib)] public static extern IntPtr el_polygons_ids(IntPtr polygons, out UIntPtr count);
        [DllImport(Lib)] public static extern IntPtr el_polygons_materials(IntPtr polygons, out UIntPtr count);
        [DllImport(Lib)] public static extern IntPtr el_polygons_cells(IntPtr polygons, out UIntPtr count);
        [DllImport(Lib)] public static extern IntPtr el_polygons_offsets(IntPtr polygons, out UIntPtr count);
        [DllImport(Lib)] public static extern IntPtr el_polygons_points(IntPtr polygons, out UIntPtr count);

        [DllImport(Lib)] public static extern void el_crossings_destroy(IntPtr crossings);
        [DllImport(Lib)] public static extern int el_crossings_copy(CrossingsHandle crossings, [Out] Crossing[] buf, UIntPtr cap, out UIntPtr needed);
        [DllImport(Lib)] public static extern IntPtr el_crossings_data(CrossingsHandle crossings, out UIntPtr count);

        [DllImport(Lib)] public static extern void el_physics_materials_init(ref NativePhysicsMaterials materials);
        [DllImport(Lib)] public static extern int el_surface_tracker_create(LandscapeHandle landscape, ref NativePhysicsMaterials materials, out SurfaceTrackerHandle tracker, ref NativeError error);
        [DllImport(Lib)] public static extern void el_surface_tracker_destroy(IntPtr tracker);
        [DllImport(Lib)] public static extern int el_surface_tracker_update(SurfaceTrackerHandle tracker, LandscapeHandle landscape, IntPtr changes, out ChainsHandle update, ref NativeError error);
        [DllImport(Lib)] public static extern int el_surface_tracker_resync(SurfaceTrackerHandle tracker, LandscapeHandle landscape, out ChainsHandle update, ref NativeError error);
        [DllImport(Lib)] public static extern int el_surface_tracker_chains(SurfaceTrackerHandle tracker, out ChainsHandle all, ref NativeError error);
        [DllImport(Lib)] public static extern void el_chains_destroy(IntPtr chains);
        [DllImport(Lib)] public static extern IntPtr el_chains_removed(IntPtr chains, out UIntPtr count);
        [DllImport(Lib)] public static extern IntPtr el_chains_info(IntPtr chains, out UIntPtr count);
        [DllImport(Lib)] public static extern IntPtr el_chains_offsets(IntPtr chains, out UIntPtr count);
        [DllImport(Lib)] public static extern IntPtr el_chains_points(IntPtr chains, out UIntPtr count);
        [DllImport(Lib)] public static extern IntPtr el_chains_materials(IntPtr chains, out UIntPtr count);
        [DllImport(Lib)] public static extern int el_island_tracker_create(LandscapeHandle landscape, ref NativePhysicsMaterials materials, out IslandTrackerHandle tracker, ref NativeError error);
        [DllImport(Lib)] public static extern void el_island_tracker_destroy(IntPtr tracker);
        [DllImport(Lib)] public static extern int el_island_tracker_update(IslandTrackerHandle tracker, LandscapeHandle landscape, IntPtr changes, out IslandsHandle found, ref NativeError error);
        [DllImport(Lib)] public static extern int el_island_tracker_resync(IslandTrackerHandle tracker, LandscapeHandle landscape, out IslandsHandle found, ref NativeError error);
        [DllImport(Lib)] public static extern int el_island_tracker_islands(IslandTrackerHandle tracker, LandscapeHandle landscape, out IslandsHandle all, ref NativeError error);
        [DllImport(Lib)] public static extern void el_islands_destroy(IntPtr islands);
        [DllImport(Lib)] public static extern IntPtr el_islands_info(IslandsHandle islands, out UIntPtr count);
        [DllImport(Lib)] public static extern IntPtr el_islands_pieces(IslandsHandle islands);
        [DllImport(Lib)] public static extern int el_detach(LandscapeHandle landscape, IslandsHandle islands, UIntPtr index, out DetachedHandle detached, ref NativeError error);
        [DllImport(Lib)] public static extern void el_detached_destroy(IntPtr detached);
        [DllImport(Lib)] public static extern int el_detached_summary(DetachedHandle detached, out DetachedInfo info, ref NativeError error);
        [DllImport(Lib)] public static extern IntPtr el_detached_changes(DetachedHandle detached);
        [DllImport(Lib)] public static extern IntPtr el_detached_regions(DetachedHandle detached);
        [DllImport(Lib)] public static extern int el_mesh_update(IntPtr changes, out MeshesHandle meshes, ref NativeError error);
        [DllImport(Lib)] public static extern int el_all_meshes(LandscapeHandle landscape, out MeshesHandle meshes, ref NativeError error);
        [DllImport(Lib)] public static extern void el_meshes_destroy(IntPtr meshes);
        [DllImport(Lib)] public static extern IntPtr el_meshes_dropped(IntPtr meshes, out UIntPtr count);
        [DllImport(Lib)] public static extern IntPtr el_meshes_polygons(IntPtr meshes);
        [DllImport(Lib)] public static extern IntPtr el_meshes_triangle_offsets(IntPtr meshes, out UIntPtr count);
        [DllImport(Lib)] public static extern IntPtr el_meshes_triangles(IntPtr meshes, out UIntPtr count);
        [DllImport(Lib)] public static extern int el_convex_pieces(Point[] points, UIntPtr count, uint maxVertices, out PolygonsHandle pieces, ref NativeError error);

        [DllImport(Lib)] public static extern int el_edits_create(out EditsHandle edits, ref NativeError error);
        [DllImport(Lib)] public static extern void el_edits_destroy(IntPtr edits);
        [DllImport(Lib)] public static extern int el_edits_carve(EditsHandle edits, ShapeHandle shape, ref NativeError error);
        [DllImport(Lib)] public static extern int el_edits_fill(EditsHandle edits, ShapeHandle shape, int material, ref NativeError error);
        [DllImport(Lib)] public static extern int el_edits_fill_empty(EditsHandle edits, ShapeHandle shape, int material, ref NativeError error);
        [DllImport(Lib)] public static extern int el_edits_replace(EditsHandle edits, ShapeHandle shape, int from, int to, ref NativeError error);
        [DllImport(Lib)] public static extern int el_edits_relabel(EditsHandle edits, ShapeHandle shape, int[] fromTo, UIntPtr pairs, ref NativeError error);
        [DllImport(Lib)] public static extern void el_game_options_init(ref NativeGameOptions options);
        [DllImport(Lib)] public static extern int el_game_driver_create(LandscapeHandle world, ref NativeGameOptions options, out GameDriverHandle driver, ref NativeError error);
        [DllImport(Lib)] public static extern void el_game_driver_destroy(IntPtr driver);
        [DllImport(Lib)] public static extern int el_game_driver_apply(GameDriverHandle driver, EditsHandle edits, out GameUpdateHandle update, ref NativeError error);
        [DllImport(Lib)] public static extern int el_game_driver_reset(GameDriverHandle driver, LandscapeHandle world, out GameUpdateHandle update, ref NativeError error);
        [DllImport(Lib)] public static extern int el_game_driver_buried(GameDriverHandle driver, ref Box box, out int buried, ref NativeError error);
        [DllImport(Lib)] public static extern int el_game_driver_landscape(GameDriverHandle driver, out LandscapeHandle world, ref NativeError error);
        [DllImport(Lib)] public static extern int el_game_driver_chains(GameDriverHandle driver, out ChainsHandle all, ref NativeError error);
        [DllImport(Lib)] public static extern UIntPtr el_game_driver_debris_waiting(GameDriverHandle driver);
        [DllImport(Lib)] public static extern void el_game_work_init(ref GameWork work);
        [DllImport(Lib)] public static extern void el_game_update_destroy(IntPtr update);
        [DllImport(Lib)] public static extern IntPtr el_game_update_changes(GameUpdateHandle update);
        [DllImport(Lib)] public static extern IntPtr el_game_update_chains(GameUpdateHandle update);
        [DllImport(Lib)] public static extern IntPtr el_game_update_meshes(GameUpdateHandle update);
        [DllImport(Lib)] public static extern IntPtr el_game_update_debris(GameUpdateHandle update, out UIntPtr count);
        [DllImport(Lib)] public static extern IntPtr el_game_update_debris_regions(GameUpdateHandle update);
        [DllImport(Lib)] public static extern IntPtr el_game_update_debris_meshes(GameUpdateHandle update);
        [DllImport(Lib)] public static extern IntPtr el_game_update_debris_pieces(GameUpdateHandle update);
        [DllImport(Lib)] public static extern int el_game_update_work(GameUpdateHandle update, ref GameWork work, ref NativeError error);

        [DllImport(Lib)] public static extern void el_bytes_destroy(IntPtr bytes);
        [DllImport(Lib)] public static extern IntPtr el_bytes_data(BytesHandle bytes, out UIntPtr size);
        [DllImport(Lib)] public static extern int el_bytes_copy(BytesHandle bytes, [Out] byte[] buf, UIntPtr cap, out UIntPtr needed);
    }

    // The structs' sizes as edgeland.h's EL_LAYOUT_ASSERTs state them.
    internal static class Layout
    {
        public static void Check()
        {
            Require(Marshal.SizeOf(typeof(Crossing)) == 168 && Marshal.OffsetOf(typeof(Crossing), "Polygon").ToInt32() == 152, "el_crossing");
            Require(Marshal.SizeOf(typeof(NativeError)) == 328, "el_error");
            Require(Marshal.SizeOf(typeof(LandscapeConfig)) == 56, "el_landscape_config");
            Require(Marshal.SizeOf(typeof(LandscapeStats)) == 48, "el_stats");
            Require(Marshal.SizeOf(typeof(AreaDelta)) == 32 && Marshal.SizeOf(typeof(Int128Value)) == 24, "el_area_delta");
            Require(Marshal.SizeOf(typeof(ChainInfo)) == 80 && Marshal.SizeOf(typeof(IslandInfo)) == 64, "el_chain_info");
            Require(Marshal.SizeOf(typeof(DetachedInfo)) == 96 && Marshal.SizeOf(typeof(NativePhysicsMaterials)) == 520, "el_detached_info");
            Require(Marshal.SizeOf(typeof(NativeGameOptions)) == 536 && Marshal.OffsetOf(typeof(NativeGameOptions), "Solid").ToInt32() == 24, "el_game_options");
            Require(Marshal.SizeOf(typeof(DebrisInfo)) == 144 && Marshal.OffsetOf(typeof(DebrisInfo), "FirstRegion").ToInt32() == 128, "el_debris_info");
            Require(Marshal.SizeOf(typeof(GameWork)) == 56, "el_game_work");
        }
        static void Require(bool ok, string what)
        {
            if (!ok) throw new InvalidOperationException("layout of " + what + " differs from edgeland.h");
        }
    }
}
