// The game driver for C# (game/README.md, "The game driver"): what a game uses. One driver owns a
// landscape and everything derived from it; each frame's edits go in as one batch and a
// GameUpdate comes out: the change set, the collision chains to remove and add (with ghost
// vertices), the render meshes to drop and build, and the islands that broke off as Debris.
using System;
using System.Collections.Generic;
using System.Numerics;

namespace Edgeland
{
    // One edit of a frame (C++ Edit): Edit.Carve(shape), Fill, FillEmpty, Replace, Relabel. The
    // shape stays the caller's; the batch copies it when the edit is applied.
    public sealed class Edit
    {
        enum Kind { Carve, Fill, FillEmpty, Replace, Relabel }
        readonly Kind kind;
        readonly Shape shape;
        readonly int[] materials;

        Edit(Kind k, Shape s, params int[] m) { kind = k; shape = s; materials = m; }

        public static Edit Carve(Shape shape) { return new Edit(Kind.Carve, shape); }
        public static Edit Fill(Shape shape, int material) { return new Edit(Kind.Fill, shape, material); }
        public static Edit FillEmpty(Shape shape, int material) { return new Edit(Kind.FillEmpty, shape, material); }
        public static Edit Replace(Shape shape, int from, int to) { return new Edit(Kind.Replace, shape, from, to); }

        // Under the shape every material of the pairs becomes its partner, all at once.
        public static Edit Relabel(Shape shape, params KeyValuePair<int, int>[] pairs)
        {
            var fromTo = new int[2 * pairs.Length];
            for (int i = 0; i < pairs.Length; ++i) { fromTo[2 * i] = pairs[i].Key; fromTo[2 * i + 1] = pairs[i].Value; }
            return new Edit(Kind.Relabel, shape, fromTo);
        }

        internal void AddTo(EditsHandle batch)
        {
            var e = Call.Error();
            int status;
            switch (kind)
            {
                case Kind.Carve: status = Native.el_edits_carve(batch, shape.Handle, ref e); break;
                case Kind.Fill: status = Native.el_edits_fill(batch, shape.Handle, materials[0], ref e); break;
                case Kind.FillEmpty: status = Native.el_edits_fill_empty(batch, shape.Handle, materials[0], ref e); break;
                case Kind.Replace: status = Native.el_edits_replace(batch, shape.Handle, materials[0], materials[1], ref e); break;
                default: status = Native.el_edits_relabel(batch, shape.Handle, materials, (UIntPtr)(materials.Length / 2), ref e); break;
            }
            EdgelandException.Check(status, ref e);
        }
    }

    // C++ GameOptions: what is solid (0 never is) and what never falls, the border as a wall,
    // meshes and debris on or off, the debris bodies' convex pieces (at most MaxPieceVertices
    // vertices, 3 or more; Box2D's 8), the island vertices one update may detach (DebrisBudget)
    // and the updates an island may wait (MaxDebrisWait).
    public sealed class GameOptions
    {
        public PhysicsMaterials Materials = new PhysicsMaterials();
        public bool Meshes = true, Debris = true;
        public uint MaxPieceVertices = 8, MaxDebrisWait = 3;
        public ulong DebrisBudget = 8192;

        internal unsafe NativeGameOptions ToNative()
        {
            var o = new NativeGameOptions();
            Native.el_game_options_init(ref o);
            o.Flags = (Meshes ? 1u : 0u) | (Debris ? 2u : 0u) | (Materials.BorderWall ? 4u : 0u);
            o.MaxPieceVertices = MaxPieceVertices;
            o.MaxDebrisWait = MaxDebrisWait;
            o.DebrisBudget = DebrisBudget;
            for (int i = 0; i < 256; ++i)
            {
                o.Solid[i] = (byte)(Materials.Solid[i] ? 1 : 0);
                o.Anchored[i] = (byte)(Materials.Anchored[i] ? 1 : 0);
            }
            return o;
        }
    }

    // An island taken out of the landscape, ready to become a dynamic body: its region as maximal
    // polygons (Material per polygon), their convex pieces (one fixture each), their meshes
    // (with GameOptions.Meshes), its exact twice area and centroid (XNum / Den, YNum / Den).
    public sealed class Debris
    {
        public Box Bounds;
        public Polygon[] Regions, Pieces;
        public Mesh[] Meshes;
        public BigInteger TwiceArea, CentroidXNum, CentroidYNum, CentroidDen;
    }

    // What one driver call changed: apply it between two physics steps. The change set keeps the
    // C update alive for the extras' MeshUpdate; Dispose() frees it at once.
    public sealed class GameUpdate : IDisposable
    {
        public ChangeSet Changes;
        public ChainUpdate Chains;
        public ulong[] MeshesDropped;
        public Mesh[] MeshesBuilt;
        public Debris[] Debris;
        public GameWork Work;
        public void Dispose() { Changes.Dispose(); }
    }

    public sealed class GameDriver : IDisposable
    {
        GameDriverHandle handle;

        // A driver over a snapshot of `world` (the Landscape stays the caller's own).
        public GameDriver(Landscape world, GameOptions options = null)
        {
            var o = (options ?? new GameOptions()).ToNative();
            var e = Call.Error();
            EdgelandException.Check(Native.el_game_driver_create(world.Raw, ref o, out handle, ref e), ref e);
        }

        // The frame's edits, in order, as one batch. A typed error (InvalidMaterialException,
        // LimitExceededException, ...) leaves the driver and its world as they were. No edits:
        // only the debris queue moves.
        public GameUpdate Apply(params Edit[] edits)
        {
            var e = Call.Error();
            EditsHandle batch;
            EdgelandException.Check(Native.el_edits_create(out batch, ref e), ref e);
            using (batch)
            {
                foreach (Edit edit in edits) edit.AddTo(batch);
                GameUpdateHandle h;
                EdgelandException.Check(Native.el_game_driver_apply(handle, batch, out h, ref e), ref e);
                return GameResults.Update(h);
            }
        }

        // The world replaced by a snapshot of `world` (an undo, a load): the update names exactly
        // what changed.
        public GameUpdate Reset(Landscape world)
        {
            var e = Call.Error();
            GameUpdateHandle h;
            EdgelandException.Check(Native.el_game_driver_reset(handle, world.Raw, out h, ref e), ref e);
            return GameResults.Update(h);
        }

        // Whether the last update's fills buried a body whose bounding box is `box`.
        public bool Buried(Box box)
        {
            var e = Call.Error();
            int buried;
            EdgelandException.Check(Native.el_game_driver_buried(handle, ref box, out buried, ref e), ref e);
            return buried != 0;
        }

        // A snapshot of the driver's world (O(1)): queries, saves, the state hash.
        public Landscape Landscape
        {
            get
            {
                var e = Call.Error();
                LandscapeHandle h;
                EdgelandException.Check(Native.el_game_driver_landscape(handle, out h, ref e), ref e);
                return Landscape.Own(h);
            }
        }

        // Every chain now, by ascending id.
        public Chain[] Chains
        {
            get
            {
                var e = Call.Error();
                ChainsHandle h;
                EdgelandException.Check(Native.el_game_driver_chains(handle, out h, ref e), ref e);
                return GameResults.Chains(h).Added;
            }
        }

        public int DebrisWaiting { get { return (int)Native.el_game_driver_debris_waiting(handle); } }

        public void Dispose() { handle.Dispose(); }
    }

    internal static unsafe partial class GameResults
    {
        public static GameUpdate Update(GameUpdateHandle h)
        {
            var work = new GameWork();
            Native.el_game_work_init(ref work);
            var e = Call.Error();
            EdgelandException.Check(Native.el_game_update_work(h, ref work, ref e), ref e);
            ulong[] dropped, unused;
            Mesh[] built = Meshes(Native.el_game_update_meshes(h), out dropped);
            Polygon[] regions = Results.Polygons(Native.el_game_update_debris_regions(h));
            Polygon[] pieces = Results.Polygons(Native.el_game_update_debris_pieces(h));
            Mesh[] meshes = Meshes(Native.el_game_update_debris_meshes(h), out unused);
            UIntPtr n;
            DebrisInfo* info = (DebrisInfo*)Native.el_game_update_debris(h, out n);
            var debris = new Debris[(int)n];
            for (int i = 0; i < debris.Length; ++i)
            {
                DebrisInfo d = info[i];
                debris[i] = new Debris
                {
                    Bounds = d.Bounds,
                    Regions = Slice(regions, d.FirstRegion, d.RegionCount),
                    Pieces = Slice(pieces, d.FirstPiece, d.PieceCount),
                    Meshes = meshes.Length > 0 ? Slice(meshes, d.FirstRegion, d.RegionCount) : new Mesh[0],
                    TwiceArea = d.TwiceArea.ToBigInteger(),
                    CentroidXNum = d.CentroidXNum.ToBigInteger(),
                    CentroidYNum = d.CentroidYNum.ToBigInteger(),
                    CentroidDen = d.CentroidDen.ToBigInteger(),
                };
            }
            return new GameUpdate
            {
                Changes = Results.Changes(h, Native.el_game_update_changes(h)),
                Chains = Chains(Native.el_game_update_chains(h)),
                MeshesDropped = dropped,
                MeshesBuilt = built,
                Debris = debris,
                Work = work,
            };
        }

        static T[] Slice<T>(T[] all, uint first, uint count)
        {
            var out_ = new T[count];
            Array.Copy(all, (int)first, out_, 0, (int)count);
            return out_;
        }
    }
}
