// SPDX-License-Identifier: BSL-1.0
// tools/common/io.hpp's output buffer: whatever mix of bytes, short and long pieces and pieces
// written in its own storage (room/commit) goes in, the file gets exactly those bytes, in
// order, at every buffer size (a piece that ends the buffer, one longer than it, room asked for
// past it).
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>
#include <cstddef>
#include <cstdio>
#include <random>
#include <string>

#include "io.hpp"

namespace {

// Everything written to `f` from its start.
std::string contents(std::FILE* f) {
  std::string s;
  std::rewind(f);
  char buf[4096];
  std::size_t n = 0;
  while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) s.append(buf, n);
  return s;
}

}  // namespace

TEST_CASE("output writes every byte in order, whatever the pieces and the buffer size") {
  for (const std::size_t capacity : {0U, 1U, 2U, 7U, 31U, 32U, 33U, 40U, 64U, 100U, 4096U}) {
    CAPTURE(capacity);
    std::mt19937 rng(static_cast<unsigned>(capacity));
    std::FILE* f = std::tmpfile();
    REQUIRE(f != nullptr);
    std::string expected;
    {
      seawire::tools::output out(f, capacity);
      for (int i = 0; i < 3000; ++i) {
        const auto letter = static_cast<char>('a' + i % 26);
        switch (rng() % 4) {
          case 0:
            out.put(letter);
            expected += letter;
            break;
          case 1: {  // up to 40 bytes: short pieces and a few past the inline copy's 32
            const std::string piece(rng() % 41, letter);
            out.put(std::string_view(piece));
            expected += piece;
            break;
          }
          case 2: {  // long pieces, some longer than the buffer
            const std::string piece(rng() % 300, letter);
            out.put(std::string_view(piece));
            expected += piece;
            break;
          }
          default: {  // written in place: room for n, k <= n kept
            const std::size_t n = 1 + rng() % 48;
            const std::size_t k = rng() % (n + 1);
            if (char* p = out.room(n)) {
              for (std::size_t j = 0; j < n; ++j) p[j] = j < k ? letter : '#';
              out.commit(k);
              expected.append(k, letter);
            } else {
              CHECK(n > capacity);  // refused only past the capacity
            }
          }
        }
      }
      out.flush();
      CHECK_FALSE(out.failed());
      CHECK(contents(f) == expected);
      out.put('!');
      expected += '!';
    }  // the destructor flushes what is left
    CHECK(contents(f) == expected);
    std::fclose(f);
  }
}
