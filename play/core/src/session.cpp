#include "edgeland/play/session.hpp"

#include <utility>

namespace edgeland::play {

Session::Session(Landscape world, const GameOptions& options, std::size_t max_undo)
    : game_(std::move(world), options), max_undo_(max_undo) {}

Edit tool_edit(const ToolEdit& edit) {
  ValidSet shape(PolygonSet{tool_shape(edit)}, Operand::kClip);
  switch (edit.tool) {
    case ToolKind::kExplosion:
    case ToolKind::kDigger:
      return Edit::carve(std::move(shape));
    case ToolKind::kFill:
      return Edit::fill(std::move(shape), edit.material);
    case ToolKind::kWater:
      return Edit::fill_empty(std::move(shape), edit.material);
    case ToolKind::kReplace:
      break;
  }
  return Edit::replace(std::move(shape), edit.from_material, edit.material);
}

GameUpdate Session::apply(const ToolEdit& edit) {
  Landscape before = world();
  GameUpdate update = game_.apply(tool_edit(edit));
  if (max_undo_ > 0) {
    if (undo_.size() == max_undo_) undo_.erase(undo_.begin());
    undo_.push_back(std::move(before));
  }
  redo_.clear();
  return update;
}

std::optional<GameUpdate> Session::undo() {
  if (undo_.empty()) return std::nullopt;
  redo_.push_back(world());
  Landscape target = std::move(undo_.back());
  undo_.pop_back();
  return game_.reset(std::move(target));
}

std::optional<GameUpdate> Session::redo() {
  if (redo_.empty()) return std::nullopt;
  undo_.push_back(world());
  Landscape target = std::move(redo_.back());
  redo_.pop_back();
  return game_.reset(std::move(target));
}

GameUpdate Session::reset(Landscape world) {
  undo_.clear();
  redo_.clear();
  return game_.reset(std::move(world));
}

GameUpdate Session::settle() { return game_.apply(std::span<const Edit>{}); }

}  // namespace edgeland::play
