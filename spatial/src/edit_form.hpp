#pragma once
// The form of an Edit (types.hpp): whether its map is what its kind says (what Edit's factories
// make), and the one material a replace changes. apply_edit and the COMMAND codec both ask.
#include <utility>

#include "edgeland/spatial/types.hpp"

namespace edgeland::detail {

// carve: every material to 0; fill: all to one; fill_empty: only 0 changed; replace: at most one
// changed; relabel: any map.
bool has_its_form(const Edit& edit);
// The one material the map changes, as (from, to); (0, 0) when it changes none.
std::pair<Material, Material> replaced(const MaterialMap& map);

}  // namespace edgeland::detail
