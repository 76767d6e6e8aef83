#pragma once
// What a hostile client sends (issue 37, item 5): garbage, oversized messages, shapes out of range
// or invalid, edits outside its box, floods; and the one edit a --diverge client applies to its
// own world only.
#include <string>

#include "edgeland/net/client.hpp"

namespace edgeland::cli {

// Sends the attacks of `mode` (garbage, oversized, out-of-range, invalid, outside, flood, all),
// waits up to `seconds` for the server's answers, prints one JSON line (the rejections by reason,
// whether it was disconnected, and each attack's verdict). Exit 0 when every attack got its typed
// rejection or a disconnect.
int run_hostile(net::Client& client, const std::string& mode, int seconds);

// A blob in the middle of the client's box (or its world): an edit the server never made.
Edit divergence(const net::Client& client);

}  // namespace edgeland::cli
