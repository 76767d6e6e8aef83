// Must NOT compile (ctest spatial.material_scoped_enum): a scoped enumerator does not convert to
// Material, and the error quotes the deleted constructor's line, which says how to pass it.
#include "edgeland/spatial/material.hpp"

enum class GameMaterial { kRock = 2 };

edgeland::Material rock() { return GameMaterial::kRock; }
