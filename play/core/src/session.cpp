#include "edgeland/play/session.hpp"

#include <utility>

namespace edgeland::play {

Session::Session(Landscape world, std::size_t max_undo)
    : world_(std::move(world)), max_undo_(max_undo) {}

ChangeSet Session::apply(const ToolEdit& edit) {
  const PolygonSet shape{tool_shape(edit)};
  Landscape before = world_;
  ChangeSet changes =
      log::apply_edit(world_, edit_kind(edit.tool), shape, edit.material, edit.from_material);
  if (max_undo_ > 0) {
    if (undo_.size() == max_undo_) undo_.erase(undo_.begin());
    undo_.push_back(std::move(before));
  }
  redo_.clear();
  return changes;
}

bool Session::undo() {
  if (undo_.empty()) return false;
  redo_.push_back(std::exchange(world_, std::move(undo_.back())));
  undo_.pop_back();
  return true;
}

bool Session::redo() {
  if (redo_.empty()) return false;
  undo_.push_back(std::exchange(world_, std::move(redo_.back())));
  redo_.pop_back();
  return true;
}

void Session::reset(Landscape world) {
  world_ = std::move(world);
  undo_.clear();
  redo_.clear();
}

}  // namespace edgeland::play
