// GameDriver (game_driver.hpp): the public door to a GameState (game_state.hpp).
#include "edgeland/game/game_driver.hpp"

#include "game_state.hpp"

namespace edgeland {

GameDriver::GameDriver(Landscape world, const GameOptions& options)
    : state_(std::make_unique<game_detail::GameState>(std::move(world), options)) {}

GameDriver::~GameDriver() = default;
GameDriver::GameDriver(GameDriver&&) noexcept = default;
GameDriver& GameDriver::operator=(GameDriver&&) noexcept = default;

GameUpdate GameDriver::apply(std::span<const Edit> edits) { return state_->apply(edits); }
GameUpdate GameDriver::reset(Landscape world) { return state_->reset(std::move(world)); }
bool GameDriver::buried(const Box64& box) const { return state_->buried(box); }
const Landscape& GameDriver::landscape() const noexcept { return state_->landscape(); }
const GameOptions& GameDriver::options() const noexcept { return state_->options(); }
const std::map<ChainId, SurfaceChain>& GameDriver::chains() const noexcept {
  return state_->chains();
}
std::size_t GameDriver::debris_waiting() const noexcept { return state_->debris_waiting(); }

}  // namespace edgeland
