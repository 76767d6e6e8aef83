// The game layer (game/README.md) for C#: surface chains and debris islands kept in step from
// change sets, detach, render meshes, convex pieces. Pass every edit's ChangeSet to every tracker,
// in order (Detach's too); Resync after a restored snapshot or a load.
using System;
using System.Collections.Generic;
using System.Numerics;

namespace Edgeland
{
    // Which materials collide (Solid; 0 never does) and which never fall (Anchored); BorderWall
    // makes the world border a wall around the non-solid parts.
    public sealed class PhysicsMaterials
    {
        public bool[] Solid = new bool[256];
        public bool[] Anchored = new bool[256];
        public bool BorderWall;

        public PhysicsMaterials() { for (int i = 1; i < 256; ++i) Solid[i] = true; }

        internal unsafe NativePhysicsMaterials ToNative()
        {
            var m = new NativePhysicsMaterials();
            Native.el_physics_materials_init(ref m);
            for (int i = 0; i < 256; ++i) { m.Solid[i] = (byte)(Solid[i] ? 1 : 0); m.Anchored[i] = (byte)(Anchored[i] ? 1 : 0); }
            m.Flags = BorderWall ? 1u : 0u;
            return m;
        }
    }

    // A surface chain: solid on its left; Materials[k] the material left of the segment after
    // point k (0 after an open chain's last point and along a border wall).
    public sealed class Chain
    {
        public ChainInfo Info;
        public Point[] Points;
        public byte[] Materials;
    }

    public sealed class ChainUpdate
    {
        public ulong[] Removed;
        public Chain[] Added;
    }

    public sealed class Island
    {
        public Box Bounds;
        public BigInteger TwiceArea;
        public Polygon[] Pieces;
    }

    // Islands found by a tracker; Game.Detach takes one of them by index. Dispose() frees them.
    public sealed class Islands : IDisposable
    {
        internal IslandsHandle Handle;
        public Island[] All;
        public void Dispose() { Handle.Dispose(); }
    }

    // An island taken out: the edit's change set (for the trackers), the region as maximal
    // polygons per material, its exact twice area and centroid (XNum / Den, YNum / Den).
    public sealed class Detached : IDisposable
    {
        internal DetachedHandle Handle;
        public ChangeSet Changes;
        public Polygon[] Regions;
        public BigInteger TwiceArea, CentroidXNum, CentroidYNum, CentroidDen;
        public void Dispose() { Handle.Dispose(); }
    }

    public sealed class Mesh
    {
        public ulong Id;
        public byte Material;
        public Point[] Vertices;
        public uint[] Triangles;  // counter-clockwise index triples into Vertices
    }

    public sealed class SurfaceTracker : IDisposable
    {
        SurfaceTrackerHandle handle;

        public SurfaceTracker(Landscape world, PhysicsMaterials materials = null)
        {
            var m = (materials ?? new PhysicsMaterials()).ToNative();
            var e = Call.Error();
            EdgelandException.Check(Native.el_surface_tracker_create(world.Raw, ref m, out handle, ref e), ref e);
        }

        public ChainUpdate Update(Landscape world, ChangeSet changes)
        {
            var e = Call.Error();
            ChainsHandle h;
            EdgelandException.Check(Native.el_surface_tracker_update(handle, world.Raw, changes.Use(), out h, ref e), ref e);
            GC.KeepAlive(changes);
            return GameResults.Chains(h);
        }

        public ChainUpdate Resync(Landscape world)
        {
            var e = Call.Error();
            ChainsHandle h;
            EdgelandException.Check(Native.el_surface_tracker_resync(handle, world.Raw, out h, ref e), ref e);
            return GameResults.Chains(h);
        }

        // Every chain the tracker holds, by ascending id.
        public Chain[] Chains
        {
            get
            {
                var e = Call.Error();
                ChainsHandle h;
                EdgelandException.Check(Native.el_surface_tracker_chains(handle, out h, ref e), ref e);
                return GameResults.Chains(h).Added;
            }
        }

        public void Dispose() { handle.Dispose(); }
    }

    public sealed class IslandTracker : IDisposable
    {
        IslandTrackerHandle handle;

        public IslandTracker(Landscape world, PhysicsMaterials materials = null)
        {
            var m = (materials ?? new PhysicsMaterials()).ToNative();
            var e = Call.Error();
            EdgelandException.Check(Native.el_island_tracker_create(world.Raw, ref m, out handle, ref e), ref e);
        }

        // The islands that exist now and did not before.
        public Islands Update(Landscape world, ChangeSet changes)
        {
            var e = Call.Error();
            IslandsHandle h;
            EdgelandException.Check(Native.el_island_tracker_update(handle, world.Raw, changes.Use(), out h, ref e), ref e);
            GC.KeepAlive(changes);
            return GameResults.Islands(h);
        }

        public Islands Resync(Landscape world)
        {
            var e = Call.Error();
            IslandsHandle h;
            EdgelandException.Check(Native.el_island_tracker_resync(handle, world.Raw, out h, ref e), ref e);
            return GameResults.Islands(h);
        }

        public Islands Current(Landscape world)
        {
            var e = Call.Error();
            IslandsHandle h;
            EdgelandException.Check(Native.el_island_tracker_islands(handle, world.Raw, out h, ref e), ref e);
            return GameResults.Islands(h);
        }

        public void Dispose() { handle.Dispose(); }
    }

    public static class Game
    {
        // Removes islands.All[index] from the world as one edit (StaleIslandException when the
        // world changed under it).
        public static Detached Detach(Landscape world, Islands islands, int index)
        {
            var e = Call.Error();
            DetachedHandle h;
            EdgelandException.Check(Native.el_detach(world.Raw, islands.Handle, (UIntPtr)index, out h, ref e), ref e);
            DetachedInfo info;
            EdgelandException.Check(Native.el_detached_summary(h, out info, ref e), ref e);
            return new Detached
            {
                Handle = h,
                Changes = Results.Changes(h, Native.el_detached_changes(h)),
                Regions = Results.Polygons(Native.el_detached_regions(h)),
                TwiceArea = info.TwiceArea.ToBigInteger(),
                CentroidXNum = info.CentroidXNum.ToBigInteger(),
                CentroidYNum = info.CentroidYNum.ToBigInteger(),
                CentroidDen = info.CentroidDen.ToBigInteger(),
            };
        }

        // The meshes an edit drops (ids) and builds.
        public static Mesh[] MeshUpdate(ChangeSet changes, out ulong[] dropped)
        {
            var e = Call.Error();
            MeshesHandle h;
            EdgelandException.Check(Native.el_mesh_update(changes.Use(), out h, ref e), ref e);
            GC.KeepAlive(changes);
            return GameResults.Meshes(h, out dropped);
        }

        public static Mesh[] AllMeshes(Landscape world)
        {
            var e = Call.Error();
            MeshesHandle h;
            EdgelandException.Check(Native.el_all_meshes(world.Raw, out h, ref e), ref e);
            ulong[] dropped;
            return GameResults.Meshes(h, out dropped);
        }

        // A valid polygon as strictly convex pieces of at most maxVertices vertices.
        public static Point[][] ConvexPieces(Point[] polygon, uint maxVertices = 8)
        {
            var e = Call.Error();
            PolygonsHandle h;
            EdgelandException.Check(Native.el_convex_pieces(polygon, (UIntPtr)polygon.Length, maxVertices, out h, ref e), ref e);
            using (h)
            {
                Polygon[] pieces = Results.Polygons(h.DangerousGetHandle());
                var out_ = new Point[pieces.Length][];
                for (int i = 0; i < pieces.Length; ++i) out_[i] = pieces[i].Points;
                return out_;
            }
        }
    }

    internal static unsafe partial class GameResults
    {
        public static ChainUpdate Chains(ChainsHandle h)
        {
            using (h) return Chains(h.DangerousGetHandle());
        }

        // The chains behind a pointer (owned by a handle the caller keeps alive).
        public static ChainUpdate Chains(IntPtr h)
        {
            UIntPtr n;
            ulong* removed = (ulong*)Native.el_chains_removed(h, out n);
            var r = new ulong[(int)n];
            for (int i = 0; i < r.Length; ++i) r[i] = removed[i];
            ChainInfo* info = (ChainInfo*)Native.el_chains_info(h, out n);
            int count = (int)n;
            uint* offsets = (uint*)Native.el_chains_offsets(h, out n);
            Point* points = (Point*)Native.el_chains_points(h, out n);
            byte* materials = (byte*)Native.el_chains_materials(h, out n);
            var chains = new Chain[count];
            for (int i = 0; i < count; ++i)
            {
                int size = (int)(offsets[i + 1] - offsets[i]);
                var c = new Chain { Info = info[i], Points = new Point[size], Materials = new byte[size] };
                for (int k = 0; k < size; ++k) { c.Points[k] = points[offsets[i] + k]; c.Materials[k] = materials[offsets[i] + k]; }
                chains[i] = c;
            }
            return new ChainUpdate { Removed = r, Added = chains };
        }

        public static Islands Islands(IslandsHandle h)
        {
            UIntPtr n;
            IslandInfo* info = (IslandInfo*)Native.el_islands_info(h, out n);
            Polygon[] pieces = Results.Polygons(Native.el_islands_pieces(h));
            var all = new Island[(int)n];
            for (int i = 0; i < all.Length; ++i)
            {
                var p = new Polygon[info[i].PieceCount];
                Array.Copy(pieces, (int)info[i].FirstPiece, p, 0, p.Length);
                all[i] = new Island { Bounds = info[i].Bounds, TwiceArea = info[i].TwiceArea.ToBigInteger(), Pieces = p };
            }
            return new Islands { Handle = h, All = all };
        }

        public static Mesh[] Meshes(MeshesHandle h, out ulong[] dropped)
        {
            using (h) return Meshes(h.DangerousGetHandle(), out dropped);
        }

        // The meshes behind a pointer (owned by a handle the caller keeps alive).
        public static Mesh[] Meshes(IntPtr h, out ulong[] dropped)
        {
            UIntPtr n;
            ulong* d = (ulong*)Native.el_meshes_dropped(h, out n);
            dropped = new ulong[(int)n];
            for (int i = 0; i < dropped.Length; ++i) dropped[i] = d[i];
            Polygon[] polygons = Results.Polygons(Native.el_meshes_polygons(h));
            uint* offsets = (uint*)Native.el_meshes_triangle_offsets(h, out n);
            uint* triangles = (uint*)Native.el_meshes_triangles(h, out n);
            var meshes = new Mesh[polygons.Length];
            for (int i = 0; i < meshes.Length; ++i)
            {
                var t = new uint[3 * (offsets[i + 1] - offsets[i])];
                for (int k = 0; k < t.Length; ++k) t[k] = triangles[3 * offsets[i] + k];
                meshes[i] = new Mesh { Id = polygons[i].Id, Material = polygons[i].Material, Vertices = polygons[i].Points, Triangles = t };
            }
            return meshes;
        }
    }
}
