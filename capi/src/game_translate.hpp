#pragma once
// The game layer's C++ values to the arrays of edgeland.h's game handles (el_chains, el_meshes):
// field for field, shared by the trackers' functions (game.cpp) and the driver's (driver.cpp).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "edgeland/game/game_types.hpp"
#include "handles.hpp"

namespace edgeland::capi {

// n as a 32-bit count (offsets and indices of results are 32 bits): EL_LIMIT_EXCEEDED beyond.
std::uint32_t checked_count(std::size_t n);

// Appends one chain (its info, points and materials) to the arrays.
void append(ChainsHandle& out, ChainId id, const SurfaceChain& chain);
// The ids removed and the chains added.
void append_chains(ChainsHandle& out, const ChainUpdate& update);
// Appends meshes (polygons with their own vertices, triangles as index triples).
void append_meshes(MeshesHandle& out, const std::vector<PolygonMesh>& built);

}  // namespace edgeland::capi
