#pragma once
// The landscape edit log's vocabulary and lines (README.md "Landscape edit logs"; the grammar in
// io/landscape_log.hpp): one keyword table and the writing of every line. The landscape records
// its log with it (Landscape::start_log, spatial/src/edit_log.cpp) and edgeland::io reads logs
// through the same table (io/landscape_log.hpp), so the recorder and the reader cannot drift
// apart. The format is io's; this part of it sits in spatial because the landscape writes it and
// spatial cannot include io. An edit's kind is Edit::Kind (types.hpp): the kinds a log writes.
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "edgeland/kernel/bbox.hpp"
#include "edgeland/kernel/export.hpp"
#include "edgeland/kernel/polygon.hpp"
#include "edgeland/spatial/material.hpp"
#include "edgeland/spatial/types.hpp"

namespace edgeland::log {

// The edits a log line can hold (carve, fill, fill_empty, replace, relabel): Edit's kinds.
using LandscapeEditKind = Edit::Kind;

// The first line's keyword: `world X0 Y0 X1 Y1 [MATERIAL]`.
inline constexpr std::string_view kWorldKeyword = "world";

// A frame batch's keyword (Landscape::apply_batch): `batch EDIT | EDIT | ...`, each EDIT an edit
// line's words without its line break, separated by kBatchSeparator (no WKT holds one).
inline constexpr std::string_view kBatchKeyword = "batch";
inline constexpr char kBatchSeparator = '|';

// An edit's keyword, and how many material numbers stand between it and the WKT shape: none
// (carve), MATERIAL (fill, fill_empty), FROM TO (replace), or any number of FROM TO pairs
// (relabel: -1).
struct EditKeyword {
  std::string_view word;
  LandscapeEditKind kind;
  int materials;
};
inline constexpr std::array<EditKeyword, 5> kEditKeywords{
    {{"carve", LandscapeEditKind::kCarve, 0},
     {"fill", LandscapeEditKind::kFill, 1},
     {"fill_empty", LandscapeEditKind::kFillEmpty, 1},
     {"replace", LandscapeEditKind::kReplace, 2},
     {"relabel", LandscapeEditKind::kRelabel, -1}}};

// The table's entry for a word; nullptr when it is no edit keyword.
constexpr const EditKeyword* find_edit_keyword(std::string_view word) noexcept {
  for (const EditKeyword& k : kEditKeywords)
    if (k.word == word) return &k;
  return nullptr;
}

// The table's entry for a kind (every kind has one).
constexpr const EditKeyword& edit_keyword(LandscapeEditKind kind) noexcept {
  for (const EditKeyword& k : kEditKeywords)
    if (k.kind == kind) return k;
  return kEditKeywords.front();  // not reached: every kind is in the table
}

// "world X0 Y0 X1 Y1[ M]\n" (M only for a filled world).
EDGELAND_EXPORT std::string world_line(const Box64& world, Material fill);

// "carve WKT\n", "fill M WKT\n", "fill_empty M WKT\n", "replace FROM TO WKT\n": `material` is
// fill's and fill_empty's M and replace's TO, `from` replace's FROM (unused by the others). A
// relabel here is the replace of `from` by `material` (the whole map: relabel_line).
EDGELAND_EXPORT std::string edit_line(LandscapeEditKind kind, const PolygonSet& shape,
                                      Material material = kEmpty, Material from = kEmpty);

// "relabel [FROM TO]... WKT\n": the pairs where the map changes a material, ascending.
EDGELAND_EXPORT std::string relabel_line(const PolygonSet& shape, const MaterialMap& map);

// The line of an Edit (a batch's edit): its kind's line with the materials its map gives, or
// the relabel line when the map is not of its kind's form (what apply_edit then does too,
// delta.hpp). A replace that changes nothing is "replace 0 0".
EDGELAND_EXPORT std::string edit_line(const Edit& edit);

// "batch EDIT | EDIT | ...\n": the edits of a batch in order, each as edit_line(const Edit&)
// writes it, without its line break.
EDGELAND_EXPORT std::string batch_line(std::span<const Edit> edits);

}  // namespace edgeland::log
