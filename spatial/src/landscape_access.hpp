#pragma once
// The landscape's private state for the parts of spatial/src that are not members.
#include "node.hpp"

namespace edgeland {

struct LandscapeAccess {
  static const Box64& world(const Landscape& l) { return l.world_; }
  static const LandscapeConfig& config(const Landscape& l) { return l.config_; }
  static const detail::NodePtr& root(const Landscape& l) { return l.root_; }
  static PolygonId next_id(const Landscape& l) { return l.next_id_; }
  static const Landscape::AreaTable& areas(const Landscape& l) { return *l.areas_; }
  static Material initial_fill(const Landscape& l) { return l.initial_fill_; }
  static std::uint64_t edits(const Landscape& l) { return l.edits_; }
  static const std::shared_ptr<const Landscape::LogLine>& log(const Landscape& l) { return l.log_; }
  static void set_log(Landscape& l, std::shared_ptr<const Landscape::LogLine> last) {
    l.log_ = std::move(last);
  }
};

}  // namespace edgeland
