#pragma once
// The helper's side of oracle/peers/served_child.hpp: `HELPER --serve PEER` reads requests
// "IN<TAB>OUT" (oracle/peers/peer_exchange.hpp files) on stdin until EOF, runs the peer on
// each and writes one reply line "CODE MESSAGE" on fd 3, CODE being the exit code a
// one-shot run would have had (0 answered, 3 refused, 4 not built in).
#include <functional>
#include <string>

namespace dtlab {

using PeerRequest = std::function<void(const std::string& in, const std::string& out)>;

// Runs one request; returns its code and sets `message` (the exception's text).
int run_peer_request(const PeerRequest& run, const std::string& in, const std::string& out, std::string& message);

// The --serve loop; returns the helper's exit status (0 at EOF, 2 without fd 3).
int serve_peer_requests(const PeerRequest& run);

}  // namespace dtlab
