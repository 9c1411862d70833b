// SPDX-License-Identifier: BSL-1.0
// The programs' buffered output (tools/common/io.hpp): what goes in comes out byte for byte,
// whatever the sizes of the pieces and wherever the end of the buffer falls among them.

#include <catch2/catch.hpp>
#include <cstddef>
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

#include "../tools/common/io.hpp"
#include "support.hpp"

namespace {

std::string random_bytes(support::prng& g, std::size_t n) {
  std::string s(n, '\0');
  for (char& c : s) c = static_cast<char>(g.next());
  return s;
}

std::string read_back(std::FILE* f) {
  std::string all;
  std::rewind(f);
  char chunk[4096];
  for (std::size_t n; (n = std::fread(chunk, 1, sizeof chunk, f)) > 0;) all.append(chunk, n);
  return all;
}

}  // namespace

TEST_CASE("output writes every piece in order, across its flushes") {
  support::prng g{43};
  for (const std::size_t capacity : {1U, 7U, 31U, 32U, 33U, 64U, 1000U}) {
    INFO("capacity " << capacity);
    std::FILE* f = std::tmpfile();
    REQUIRE(f != nullptr);
    std::string want;
    {
      seawire::tools::output out(f, capacity);
      for (int k = 0; k < 3000; ++k) {
        if (g.below(5) == 0) {
          const char c = static_cast<char>(g.next());
          out.put(c);
          want += c;
        } else {
          // Mostly short pieces (the inline path), some longer than the buffer.
          const std::size_t n = g.below(4) == 0 ? g.below(2 * capacity + 80) : g.below(33);
          const std::string piece = random_bytes(g, n);
          out.put(std::string_view(piece));
          want += piece;
        }
      }
      out.flush();
      CHECK_FALSE(out.failed());
    }
    CHECK(read_back(f) == want);
    std::fclose(f);
  }
}

TEST_CASE("for_each_line gives every line whole, across the reader's chunks") {
  // Lines of every length around the 64 KiB chunk, CR LF and LF endings, an empty line, and a
  // last line without an ending.
  support::prng g{44};
  std::vector<std::string> want;
  std::string text;
  while (text.size() < 3 * seawire::tools::read_chunk) {
    const std::size_t n = g.below(8) == 0 ? g.below(seawire::tools::read_chunk + 100) : g.below(90);
    std::string l(n, 'x');
    for (char& c : l) c = static_cast<char>('a' + g.below(26));
    if (g.coin()) l += '\r';
    if (g.below(20) == 0) l.clear();
    text += l;
    text += '\n';
    want.push_back(l);
  }
  text += "last";
  want.emplace_back("last");
  std::FILE* f = std::tmpfile();
  REQUIRE(f != nullptr);
  REQUIRE(std::fwrite(text.data(), 1, text.size(), f) == text.size());
  REQUIRE(std::fflush(f) == 0);
  std::rewind(f);
  seawire::tools::chunk_reader in(fileno(f));
  std::vector<std::string> got;
  seawire::tools::for_each_line(in, [&](std::string_view l) { got.emplace_back(l); });
  CHECK_FALSE(in.failed());
  CHECK(got == want);
  std::fclose(f);
}
