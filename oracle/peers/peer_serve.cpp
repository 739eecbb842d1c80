#include "oracle/peers/peer_serve.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <exception>
#include <iostream>

#include "oracle/peers/peer_programs.hpp"

namespace dtlab {

int run_peer_request(const PeerRequest& run, const std::string& in, const std::string& out, std::string& message) {
  return run_peer_work([&] { run(in, out); }, message);
}

int serve_peer_requests(const PeerRequest& run) {
  std::FILE* reply = fdopen(3, "w");
  if (!reply) {
    std::fprintf(stderr, "--serve: no reply channel on fd 3\n");
    return 2;
  }
  std::string line;
  while (std::getline(std::cin, line)) {
    const auto tab = line.find('\t');
    std::string message;
    const int code = tab == std::string::npos
                         ? (message = "bad request: " + line, 2)
                         : run_peer_request(run, line.substr(0, tab), line.substr(tab + 1), message);
    for (char& c : message)
      if (c == '\n' || c == '\r') c = ' ';
    std::fflush(stdout);
    std::fprintf(reply, "%d %s\n", code, message.c_str());
    std::fflush(reply);
  }
  return 0;
}

}  // namespace dtlab
