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
// A driver an update failed in (running out of memory) is made anew from `world`, and the
// update takes the game from what it was last told to the new state (game_state.hpp rebuilt);
// if that runs out of memory too, the failed state stays and reset() may be called again.
GameUpdate GameDriver::reset(Landscape world) {
  if (!state_->broken()) return state_->reset(std::move(world));
  GameUpdate out;
  std::unique_ptr<game_detail::GameState> fresh =
      game_detail::GameState::rebuilt(*state_, std::move(world), out);
  state_ = std::move(fresh);
  return out;
}
void GameDriver::update_lost() noexcept { state_->update_lost(); }
bool GameDriver::buried(const Box64& box) const { return state_->buried(box); }
const Landscape& GameDriver::landscape() const noexcept { return state_->landscape(); }
const GameOptions& GameDriver::options() const noexcept { return state_->options(); }
const std::map<ChainId, SurfaceChain>& GameDriver::chains() const noexcept {
  return state_->chains();
}
std::size_t GameDriver::debris_waiting() const noexcept { return state_->debris_waiting(); }

}  // namespace edgeland
