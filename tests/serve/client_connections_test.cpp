// The connections waiting for a request: past the limit of one client, or of all, the one that has
// waited longest is shut down; connections being answered never are (unit, on socket pairs).
#include "serve/client_connections.h"

#include <gtest/gtest.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <array>
#include <vector>

namespace urdfsnap::serve {
namespace {

// A connected pair of sockets: the server's end (registered) and the client's.
struct Pair {
  Pair(const Pair&) = delete;
  Pair& operator=(const Pair&) = delete;
  Pair() { EXPECT_EQ(socketpair(AF_UNIX, SOCK_STREAM, 0, ends.data()), 0); }
  ~Pair() {
    close(ends[0]);
    close(ends[1]);
  }
  // Whether the server's end was shut down: a read returns at once with nothing.
  bool shut() const {
    pollfd p{ends[0], POLLIN, 0};
    char byte;
    return poll(&p, 1, 0) == 1 && recv(ends[0], &byte, 1, MSG_DONTWAIT) == 0;
  }
  std::array<int, 2> ends{-1, -1};
};

TEST(ClientConnections, TheLongestWaitingOfAClientMakesWayForItsNewOne) {
  ClientConnections connections({2, 10});
  std::vector<Pair> pairs(4);
  const auto a = connections.Open("10.0.0.1", pairs[0].ends[0]);
  const auto b = connections.Open("10.0.0.1", pairs[1].ends[0]);
  connections.Open("10.0.0.2", pairs[2].ends[0]);  // another client: its own limit
  EXPECT_FALSE(pairs[0].shut());
  connections.Answer(a);  // a sent its request: being answered, never shut down for a newcomer
  connections.Open("10.0.0.1", pairs[3].ends[0]);
  EXPECT_FALSE(pairs[0].shut());
  EXPECT_FALSE(pairs[1].shut());
  connections.Wait(a);  // a waits for its next request (keep-alive): now three wait, b longest
  EXPECT_TRUE(pairs[1].shut());
  EXPECT_FALSE(pairs[0].shut());
  EXPECT_FALSE(pairs[2].shut());
  EXPECT_FALSE(pairs[3].shut());
  connections.Close(b);
  EXPECT_EQ(connections.waiting(), 3u);
}

TEST(ClientConnections, AllClientsTogetherHaveALimitToo) {
  ClientConnections connections({8, 3});
  std::vector<Pair> pairs(5);
  for (int i = 0; i < 5; ++i) connections.Open("10.0.0." + std::to_string(i), pairs[i].ends[0]);
  EXPECT_TRUE(pairs[0].shut());
  EXPECT_TRUE(pairs[1].shut());
  EXPECT_FALSE(pairs[2].shut());
  EXPECT_EQ(connections.waiting(), 3u);
}

}  // namespace
}  // namespace urdfsnap::serve
