// SPDX-License-Identifier: BSL-1.0
#include <catch2/catch.hpp>

#include <set>
#include <string>
#include <string_view>
#include <type_traits>

#include "seawire/error.hpp"

namespace {

using seawire::errc;
using underlying = std::underlying_type_t<errc>;

constexpr auto first = static_cast<underlying>(errc::ok);
constexpr auto last = static_cast<underlying>(errc::trailing_characters);

constexpr bool is_identifier(std::string_view s) {
  if (s.empty() || (s.front() >= '0' && s.front() <= '9')) return false;
  for (char c : s) {
    if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_')) return false;
  }
  return true;
}

}  // namespace

// Usable in constant expressions, like the rest of the library.
static_assert(seawire::name(errc::ok) == "ok");
static_assert(seawire::name(errc::checksum_mismatch) == "checksum_mismatch");
static_assert(!seawire::message(errc::truncated).empty());
static_assert(seawire::result<int>{}.ok());
static_assert(!seawire::result<int>{.value = 1, .ec = errc::bad_number}.ok());

TEST_CASE("every errc has a distinct identifier-like name and a distinct message") {
  std::set<std::string_view> names;
  std::set<std::string_view> messages;
  for (unsigned v = first; v <= last; ++v) {
    const auto e = static_cast<errc>(v);
    const std::string_view name = seawire::name(e);
    const std::string_view message = seawire::message(e);
    INFO("errc value " << v << " name '" << std::string(name) << "' message '"
                       << std::string(message) << "'");
    CHECK(is_identifier(name));
    CHECK(name != "unknown_error");
    CHECK(message != "unknown error");
    CHECK_FALSE(message.empty());
    CHECK(names.insert(name).second);
    CHECK(messages.insert(message).second);
  }
  CHECK(names.size() == last - first + 1u);
}

TEST_CASE("errc::trailing_characters is the last value") {
  // If this fails, a value was added after trailing_characters: move `last` above to the
  // new last value.
  const auto past_end = static_cast<errc>(last + 1);
  CHECK(seawire::name(past_end) == "unknown_error");
  CHECK(seawire::message(past_end) == "unknown error");
}

TEST_CASE("result<T> is true exactly when ec is ok") {
  STATIC_REQUIRE_FALSE(std::is_convertible_v<seawire::result<int>, bool>);  // explicit only
  STATIC_REQUIRE(std::is_constructible_v<bool, seawire::result<int>>);

  const seawire::result<int> fine{.value = 42};
  CHECK(static_cast<bool>(fine));
  CHECK(fine.ok());
  CHECK(fine.value == 42);
  CHECK(fine.field == 0);
  CHECK(fine.column == 0);

  for (unsigned v = first + 1; v <= last; ++v) {
    const auto e = static_cast<errc>(v);
    INFO("errc " << std::string(seawire::name(e)));
    const seawire::result<int> failed{.ec = e, .field = 2, .column = 7};
    CHECK_FALSE(static_cast<bool>(failed));
    CHECK_FALSE(failed.ok());
    if (failed) FAIL("a failed result must not test true in an if");
  }

  struct point {
    int x = 0;
    int y = 0;
  };
  seawire::result<point> r{};
  CHECK(r);
  r.ec = errc::out_of_range;
  CHECK_FALSE(r);
  r.ec = errc::ok;
  CHECK(r);
}
