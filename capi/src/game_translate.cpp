#include "game_translate.hpp"

#include <limits>

#include "border.hpp"
#include "translate.hpp"

namespace edgeland::capi {

std::uint32_t checked_count(std::size_t n) {
  if (n > std::numeric_limits<std::uint32_t>::max()) {
    throw BorderError(EL_LIMIT_EXCEEDED, "more than 2^32 - 1 entries in one result");
  }
  return static_cast<std::uint32_t>(n);
}

void append(ChainsHandle& out, ChainId id, const SurfaceChain& c) {
  el_chain_info info{};
  info.cell = to_c(c.cell);
  info.ghost_prev = to_c(c.ghost_prev);
  info.ghost_next = to_c(c.ghost_next);
  info.id = id;
  info.closed = c.closed ? 1 : 0;
  out.info.push_back(info);
  for (std::size_t k = 0; k < c.points.size(); ++k) {
    out.points.push_back(to_c(c.points[k]));
    out.materials.push_back(k < c.materials.size() ? c.materials[k].value() : 0);
  }
  out.offsets.push_back(checked_count(out.points.size()));
}

void append_chains(ChainsHandle& out, const ChainUpdate& update) {
  out.removed.insert(out.removed.end(), update.removed.begin(), update.removed.end());
  for (const auto& [id, chain] : update.added) append(out, id, chain);
}

void append_meshes(MeshesHandle& out, const std::vector<PolygonMesh>& built) {
  for (const PolygonMesh& mesh : built) {
    append(out.polygons, mesh.id, mesh.material, Box64{}, mesh.vertices);
    for (const Triangle& t : mesh.triangles)
      out.triangles.insert(out.triangles.end(), {t.a, t.b, t.c});
    out.triangle_offsets.push_back(checked_count(out.triangles.size() / 3));
  }
}

}  // namespace edgeland::capi
