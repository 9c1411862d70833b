// SPDX-License-Identifier: BSL-1.0
// NMEA 2000 declarations a number, a lookup or a table cannot hold exactly must not compile.
// Each ctest case compiles this file with one CASE defined and expects the declaration's message;
// CASE ok must compile (so a failure is the declaration's, not a broken file).
#include <array>
#include <cstdint>
#include <string_view>

#include "seawire/nmea2000/field.hpp"

namespace n2k = seawire::nmea2000;

struct item {
  n2k::unsigned_number<16> value;
  static constexpr auto n2k_item = n2k::describe_item(n2k::field<&item::value>("value", "Value"));
  constexpr bool operator==(const item&) const noexcept = default;
};

#if defined(CASE_ok)
n2k::signed_number<64, n2k::resolution{1, -16}> wide;
n2k::unsigned_number<63> widest_unsigned;
struct msg {
  n2k::unsigned_number<8> count;
  n2k::group<item, n2k::group_capacity<item>(1)> items;
  static constexpr auto n2k =
      n2k::describe_pgn(n2k::pgn_info{1, "msg", "Msg"}, n2k::field<&msg::count>("count", "Count"),
                        n2k::repeating<&msg::items, &msg::count>("items", "Items"));
};
const auto ok_length = n2k::description_of<msg>::length;
struct with_bytes {
  n2k::unsigned_number<8> first;
  n2k::opaque_bytes<222> rest;
  static constexpr auto n2k =
      n2k::describe_pgn(n2k::pgn_info{2, "with_bytes", "With bytes"},
                        n2k::field<&with_bytes::first>("first", "First"),
                        n2k::bytes_to_end<&with_bytes::rest>("rest", "Rest"));
};
const auto ok_bytes_length = n2k::description_of<with_bytes>::length;
// A table as a function template of its struct: built where used.
struct lazy_msg {
  n2k::unsigned_number<8> first;
  template <class P>
  static constexpr auto n2k() {
    return n2k::describe_pgn(n2k::pgn_info{3, "lazy_msg", "Lazy"},
                             n2k::field<&P::first>("first", "First"));
  }
};
static_assert(n2k::description_of<lazy_msg>::length == 1);
enum class two : std::uint8_t { a = 0, b = 1 };
constexpr std::array<std::string_view, 2> lookup_names(two) noexcept { return {"a", "b"}; }
constexpr bool ok_named = n2k::lookup<two, 1>{two::b}.has_value();
#elif defined(CASE_unsigned_64)
n2k::unsigned_number<64> too_wide;
#elif defined(CASE_scale_overflow)
n2k::signed_number<64, n2k::resolution{25, -2}> too_fine;
#elif defined(CASE_wrong_capacity)
struct msg {
  n2k::unsigned_number<8> count;
  n2k::group<item, 200> items;
  static constexpr auto n2k =
      n2k::describe_pgn(n2k::pgn_info{1, "msg", "Msg"}, n2k::field<&msg::count>("count", "Count"),
                        n2k::repeating<&msg::items, &msg::count>("items", "Items"));
};
const auto bad_length = n2k::description_of<msg>::length;
#elif defined(CASE_group_not_last)
struct msg {
  n2k::unsigned_number<8> count;
  n2k::group<item, n2k::group_capacity<item>(1)> items;
  n2k::unsigned_number<8> after;
  static constexpr auto n2k =
      n2k::describe_pgn(n2k::pgn_info{1, "msg", "Msg"}, n2k::field<&msg::count>("count", "Count"),
                        n2k::repeating<&msg::items, &msg::count>("items", "Items"),
                        n2k::field<&msg::after>("after", "After"));
};
const auto bad_length = n2k::description_of<msg>::length;
#elif defined(CASE_bytes_not_last)
struct msg {
  n2k::opaque_bytes<222> rest;
  n2k::unsigned_number<8> after;
  static constexpr auto n2k = n2k::describe_pgn(n2k::pgn_info{1, "msg", "Msg"},
                                                n2k::bytes_to_end<&msg::rest>("rest", "Rest"),
                                                n2k::field<&msg::after>("after", "After"));
};
const auto bad_length = n2k::description_of<msg>::length;
#elif defined(CASE_bytes_wrong_capacity)
struct msg {
  n2k::unsigned_number<8> first;
  n2k::opaque_bytes<100> rest;
  static constexpr auto n2k =
      n2k::describe_pgn(n2k::pgn_info{1, "msg", "Msg"}, n2k::field<&msg::first>("first", "First"),
                        n2k::bytes_to_end<&msg::rest>("rest", "Rest"));
};
const auto bad_length = n2k::description_of<msg>::length;
#elif defined(CASE_two_match_rows)
enum class code : std::uint8_t { a = 0, b = 1 };
constexpr std::array<std::string_view, 2> lookup_names(code) noexcept { return {"a", "b"}; }
struct msg {
  n2k::lookup<code, 8> first = code::a;
  n2k::lookup<code, 8> second = code::b;
  static constexpr auto n2k = n2k::describe_pgn(
      n2k::pgn_info{1, "msg", "Msg"}, n2k::match<&msg::first, code::a>("first", "First"),
      n2k::match<&msg::second, code::b>("second", "Second"));
};
const auto bad_length = n2k::description_of<msg>::length;
#elif defined(CASE_lazy_table_bits)
// A table built where the PGN is used is checked there.
struct msg {
  n2k::unsigned_number<4> half;
  template <class P>
  static constexpr auto n2k() {
    return n2k::describe_pgn(n2k::pgn_info{1, "msg", "Msg"}, n2k::field<&P::half>("half", "Half"));
  }
};
const auto bad_length = n2k::description_of<msg>::length;
#elif defined(CASE_lookup_too_many_names)
// A lookup's names are checked where the lookup first reads them.
enum class three : std::uint8_t { a = 0, b = 1, c = 2 };
constexpr std::array<std::string_view, 3> lookup_names(three) noexcept { return {"a", "b", "c"}; }
constexpr bool named = n2k::lookup<three, 1>{three::a}.has_value();
#elif defined(CASE_lookup_state_name)
enum class state_named : std::uint8_t { a = 0, b = 1 };
constexpr std::array<std::string_view, 2> lookup_names(state_named) noexcept {
  return {"a", "reserved"};
}
constexpr bool named = n2k::lookup<state_named, 8>{state_named::a}.has_value();
#elif defined(CASE_signed_count)
struct msg {
  n2k::signed_number<8> count;
  n2k::group<item, n2k::group_capacity<item>(1)> items;
  static constexpr auto n2k =
      n2k::describe_pgn(n2k::pgn_info{1, "msg", "Msg"}, n2k::field<&msg::count>("count", "Count"),
                        n2k::repeating<&msg::items, &msg::count>("items", "Items"));
};
#endif
