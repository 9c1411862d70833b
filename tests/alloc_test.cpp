// SPDX-License-Identifier: BSL-1.0
// No heap allocation anywhere on a decode or encode path. This program is linked with the
// benchmarks' global operator new, which counts every allocation (bench/alloc_count.cpp); Catch
// itself allocates, so only the allocations within a measured region count. It runs every
// message type of every family through decode (by type, through its family's set, into a variant
// and through visit) and encode (into a span and by value), the framer over a byte stream, and the
// binary frame both ways. The inputs come from the benchmark corpus generator (bench/corpus.hpp)
// and are built before counting starts.

#include <array>
#include <catch2/catch.hpp>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

#include "../bench/alloc_count.hpp"
#include "../bench/corpus.hpp"
#include "seawire/anello/frame.hpp"
#include "seawire/nmea/dispatch.hpp"
#include "seawire/nmea/framer.hpp"
#include "seawire/nmea/message.hpp"
#include "seawire/nmea/sentence.hpp"

namespace {

/// Heap allocations made while `f` runs.
template <class F>
std::uint64_t allocations_in(F&& f) {
  const std::uint64_t before = seawire::bench::allocation_count();
  f();
  return seawire::bench::allocation_count() - before;
}

using namespace seawire;
namespace sb = seawire::bench;

using sb::every_message;

constexpr std::size_t lines_per_type = 64;

/// A visitor that keeps the address of the message it is handed.
struct address_of {
  std::string_view& address;
  template <class M>
  void operator()(const M&) const {
    if constexpr (nmea::message_like<M>) address = M::nmea.address;
  }
};

/// Decodes each line as T, through `Set` into a variant and through `Set::visit`, then encodes
/// the message into a span and by value; every step must succeed, and the bytes must come back.
template <class Set, class T>
void check_type(const sb::message_corpus<T>& c, const nmea::parse_policy& policy,
                std::size_t& checked) {
  std::array<char, 512> buffer{};
  for (std::size_t i = 0; i < c.size(); ++i) {
    const std::string_view line = c.lines[i];
    const result<T> typed = nmea::decode<T>(line, policy);
    REQUIRE(typed);
    const auto any = Set::decode(line, policy);
    REQUIRE(any);
    REQUIRE(std::holds_alternative<T>(any.value));
    const result<nmea::sentence_view> s = nmea::parse(line, policy);
    REQUIRE(s);
    // One visitor type for every T, so that the set's visit is compiled once, not once a type.
    std::string_view seen;
    REQUIRE(Set::visit(s.value, policy, address_of{seen}));
    REQUIRE(seen == T::nmea.address);
    const result<std::size_t> n = nmea::encode_to(typed.value, std::span<char>(buffer));
    REQUIRE(n);
    REQUIRE(std::string_view(buffer.data(), n.value) == line);
    const auto by_value = nmea::encode(std::get<T>(any.value));
    REQUIRE(by_value.view() == line);
    ++checked;
  }
}

/// check_type for each message type of the set, counting allocations around the checks only.
template <class Set, class... Ms>
void check_set(nmea::message_set<Ms...>*, const nmea::parse_policy& policy) {
  const auto one = [&](auto* tag) {
    using M = std::remove_pointer_t<decltype(tag)>;
    const sb::message_corpus<M> c = sb::corpus_of<M>(lines_per_type);  // allocates: not counted
    std::size_t checked = 0;
    INFO(M::nmea.address);
    CHECK(allocations_in([&] { check_type<Set, M>(c, policy, checked); }) == 0);
    CHECK(checked == lines_per_type);
  };
  (one(static_cast<Ms*>(nullptr)), ...);
}

}  // namespace

namespace {
int* volatile escaped = nullptr;
}  // namespace

TEST_CASE("the counting operator new sees allocations in a measured region, and only there") {
  std::vector<int> outside;
  outside.reserve(8);  // not counted
  const std::uint64_t n = allocations_in([] {
    std::vector<int> v;
    v.reserve(100);
    v.push_back(1);
    // The buffer's address escapes, so the optimizer cannot elide the allocation (clang at -O3
    // removes a new/delete pair whose memory nothing else sees).
    escaped = v.data();
  });
  CHECK(n >= 1);
  CHECK(allocations_in([] {}) == 0);
}

TEST_CASE("decode and encode of every message type of every family allocate nothing") {
  check_set<every_message>(static_cast<every_message*>(nullptr), nmea::parse_policy{});
}

TEST_CASE("each family's own set under its role's policy allocates nothing") {
#if SEAWIRE_BENCH_HAS_KINGFISHER
  check_set<kingfisher::from_vehicle>(static_cast<kingfisher::from_vehicle*>(nullptr),
                                      kingfisher::payload_policy());
  check_set<kingfisher::to_vehicle>(static_cast<kingfisher::to_vehicle*>(nullptr),
                                    kingfisher::vehicle_policy());
#endif
  check_set<sandshark::from_vehicle>(static_cast<sandshark::from_vehicle*>(nullptr),
                                     sandshark::from_vehicle_policy);
  check_set<sandshark::to_vehicle>(static_cast<sandshark::to_vehicle*>(nullptr),
                                   sandshark::to_vehicle_policy);
  check_set<robotx::reports>(static_cast<robotx::reports*>(nullptr), robotx::judge_policy);
  check_set<anello::nmea_inputs>(static_cast<anello::nmea_inputs*>(nullptr), anello::input_policy);
}

TEST_CASE("the framer over a stream in 4 KiB chunks, then decode, allocates nothing") {
  std::vector<sb::corpus> parts;  // every family's stream, one after the other
  parts.push_back(sb::rmc_gga_corpus(200));
  parts.push_back(sb::anello_inputs_corpus(200));
  parts.push_back(sb::sandshark_from_vehicle_corpus(200));
  parts.push_back(sb::sandshark_to_vehicle_corpus(200));
  parts.push_back(sb::robotx_corpus(200));
#if SEAWIRE_BENCH_HAS_KINGFISHER
  parts.push_back(sb::kingfisher_from_vehicle_corpus(200));
  parts.push_back(sb::kingfisher_to_vehicle_corpus(200));
#endif
  std::string stream;
  std::size_t expected = 0;
  for (const sb::corpus& p : parts) {
    stream += p.bytes;
    expected += p.size();
  }
  auto framer = std::make_unique<nmea::framer<1024>>();  // allocated before counting
  std::size_t lines = 0;
  std::size_t decoded = 0;
  CHECK(allocations_in([&] {
          const std::string_view bytes = stream;
          for (std::size_t at = 0; at < bytes.size(); at += 4096) {
            framer->feed(bytes.substr(at, 4096));
            while (const std::optional<nmea::framed_line> l = framer->next()) {
              ++lines;
              const auto r = every_message::decode(l->text);
              if (r && r.value.index() != 0) ++decoded;
            }
          }
          (void)framer->finish();
        }) == 0);
  CHECK(lines == expected);
  CHECK(decoded == expected);
}

TEST_CASE(
    "the 0xAB00 binary frame, decoded, checked, converted, built and encoded, allocates "
    "nothing") {
  const std::vector<std::uint8_t> frames = sb::anello_frames(64);
  std::size_t good = 0;
  CHECK(allocations_in([&] {
          const std::span<const std::uint8_t> all = frames;
          anello::frame_bytes out{};
          for (std::size_t at = 0; at < all.size(); at += anello::frame_size) {
            const result<anello::sensor_frame_raw> f = anello::decode_frame(all.subspan(at));
            if (!f || !anello::validate(f.value)) continue;
            const anello::sensor_values v = anello::to_values(f.value);
            const result<anello::sensor_frame_raw> built = anello::build_frame(v);
            if (!built) continue;
            if (!anello::encode_frame(built.value, out)) continue;
            if (anello::encode_frame(f.value) != out) continue;
            ++good;
          }
        }) == 0);
  CHECK(good == 64);
}
