// SPDX-License-Identifier: BSL-1.0
// RobotX over time: Hawaii Standard Time, the heartbeat scheduler and the judges' validator,
// all on simulated clocks.
#include "seawire/robotx/heartbeat.hpp"
#include "seawire/robotx/hst.hpp"
#include "seawire/robotx/messages.hpp"
#include "seawire/robotx/validator.hpp"

#include <catch2/catch.hpp>

#include <chrono>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "support.hpp"

namespace {

using namespace support;

using namespace std::chrono;
using namespace std::chrono_literals;
using namespace std::string_view_literals;
namespace nmea = seawire::nmea;
namespace rx = seawire::robotx;
using seawire::errc;

constexpr rx::instant utc(year_month_day d, nanoseconds since_midnight = {}) {
  return rx::instant{sys_days{d}} + since_midnight;
}

constexpr rx::hst_stamp hst(std::uint16_t y, std::uint8_t mo, std::uint8_t d, std::uint8_t h,
                            std::uint8_t mi, std::uint8_t s) {
  return {{y, mo, d}, {h, mi, s, 0, 0}};
}

// The spec's stamp, 10 Dec 2018 16:12:29 HST, is 11 Dec 2018 02:12:29 UTC.
constexpr rx::instant seed_utc = utc(2018y / 12 / 11, 2h + 12min + 29s);
static_assert(rx::to_hst(seed_utc).value == hst(2018, 12, 10, 16, 12, 29));
static_assert(rx::from_hst(hst(2018, 12, 10, 16, 12, 29)).value == seed_utc);
// Year end, both sides of HST midnight.
static_assert(rx::to_hst(utc(2019y / 1 / 1, 9h + 59min + 59s)).value ==
              hst(2018, 12, 31, 23, 59, 59));
static_assert(rx::to_hst(utc(2019y / 1 / 1, 10h)).value == hst(2019, 1, 1, 0, 0, 0));

rx::rxhrb heartbeat_content() {
  rx::rxhrb hb;
  hb.team_id = "AUVSI";
  hb.lat = nmea::decimal_latitude::from_degrees(21.31198).value;
  hb.lon = nmea::decimal_longitude::from_degrees(-157.88972).value;
  hb.system_mode = rx::system_mode::autonomous;
  hb.auv_status = rx::auv_status::stowed;
  return hb;
}

rx::rxcod code_report(std::string_view pattern) {
  rx::rxcod m;
  m.team_id = "AUVSI";
  m.light_pattern = rx::light_pattern::from(pattern).value;
  return m;
}

// Everything a scheduler sends at `now`.
std::vector<rx::outgoing> drain(rx::scheduler& s, rx::instant now) {
  std::vector<rx::outgoing> out;
  while (auto o = s.poll(now)) out.push_back(*o);
  return out;
}

std::vector<std::string> rules_of(const rx::finding_list& l) {
  std::vector<std::string> out;
  for (const auto& f : l) {
    out.push_back(std::string(rx::name(f.broken)) + " " + std::string(f.address.view()) + " " +
                  std::to_string(f.field) + " " + std::string(seawire::name(f.ec)));
  }
  return out;
}

// `line` checked by `v` at `at`: CHECKs that its findings are exactly `rules` (rules_of, in
// order), and returns the verdict for what else a test asks of it.
rx::verdict checked(rx::validator& v, std::string_view line, rx::instant at,
                    const std::vector<std::string>& rules) {
  INFO("line: " << line);
  rx::verdict verdict = v.check(line, at);
  CHECK(rules_of(verdict.findings) == rules);
  return verdict;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// HST

TEST_CASE("HST: UTC-10 across midnight, month ends and year ends") {
  struct row {
    rx::instant in;
    rx::hst_stamp out;
  };
  const row rows[] = {
      {utc(2019y / 1 / 1, 9h + 59min + 59s), hst(2018, 12, 31, 23, 59, 59)},
      {utc(2019y / 1 / 1, 10h), hst(2019, 1, 1, 0, 0, 0)},
      {utc(2018y / 12 / 11), hst(2018, 12, 10, 14, 0, 0)},  // UTC midnight
      {utc(2018y / 12 / 11, 9h + 59min + 59s), hst(2018, 12, 10, 23, 59, 59)},
      {utc(2018y / 12 / 11, 10h), hst(2018, 12, 11, 0, 0, 0)},               // HST midnight
      {utc(2018y / 3 / 1, 9h + 59min + 59s), hst(2018, 2, 28, 23, 59, 59)},  // not a leap year
      {utc(2018y / 3 / 1, 10h), hst(2018, 3, 1, 0, 0, 0)},
      {utc(2020y / 3 / 1, 9h + 59min + 59s), hst(2020, 2, 29, 23, 59, 59)},  // leap year
      {utc(2020y / 2 / 29, 10h), hst(2020, 2, 29, 0, 0, 0)},
      {utc(2020y / 2 / 29, 9h), hst(2020, 2, 28, 23, 0, 0)},
      {utc(2000y / 3 / 1, 5h), hst(2000, 2, 29, 19, 0, 0)},              // 2000: divisible by 400
      {utc(2018y / 5 / 1, 3h + 4min + 5s), hst(2018, 4, 30, 17, 4, 5)},  // 30-day month
      {utc(1980y / 1 / 1, 10h), hst(1980, 1, 1, 0, 0, 0)},
      {utc(2079y / 12 / 31, 23h + 59min + 59s), hst(2079, 12, 31, 13, 59, 59)},
  };
  for (const row& r : rows) {
    const auto got = rx::to_hst(r.in);
    INFO(r.in.time_since_epoch().count());
    REQUIRE(got.ok());
    CHECK(got.value == r.out);
    const auto back = rx::from_hst(got.value);
    REQUIRE(back.ok());
    CHECK(back.value == r.in);
  }
}

TEST_CASE("HST: fractions of a second are truncated, never rounded up") {
  const auto t = rx::to_hst(utc(2019y / 1 / 1, 9h + 59min + 59s + 999'999'999ns));
  CHECK(t.value == hst(2018, 12, 31, 23, 59, 59));
  CHECK(t.value.time.places == 0);
  // Before 1970 too (floor, not truncation toward zero): 1969 is out of range anyway, but the
  // local reading is right.
  const auto local = rx::to_hst_local(sys_seconds{} - 1s + 500ms);
  CHECK(local == local_days{1969y / 12 / 31} + 13h + 59min + 59s);
}

TEST_CASE("HST: years a two-digit year cannot name are refused") {
  CHECK(rx::to_hst(utc(1980y / 1 / 1, 9h + 59min + 59s)).ec == errc::out_of_range);  // 1979 HST
  CHECK(rx::to_hst(utc(2080y / 1 / 1, 10h)).ec == errc::out_of_range);
  CHECK(rx::to_hst(utc(2080y / 1 / 1, 9h)).ok());  // still 2079 in Hawaii
}

TEST_CASE("HST: from_hst refuses what the codecs refuse") {
  CHECK(rx::from_hst({2019, 2, 29}, {0, 0, 0, 0, 0}).ec == errc::day_out_of_range);
  CHECK(rx::from_hst({2019, 13, 1}, {0, 0, 0, 0, 0}).ec == errc::month_out_of_range);
  CHECK(rx::from_hst({2019, 1, 1}, {24, 0, 0, 0, 0}).ec == errc::hour_out_of_range);
  const auto frac = rx::from_hst({2019, 1, 1}, {0, 0, 1, 25, 2});
  REQUIRE(frac.ok());
  CHECK(frac.value == utc(2019y / 1 / 1, 10h + 1s + 250ms));
}

TEST_CASE("HST: round trip every 3607 s over 1980..2079") {
  for (auto t = utc(1980y / 1 / 1, 10h); t < utc(2080y / 1 / 1); t += 3607s * 97) {
    const auto s = rx::to_hst(t);
    REQUIRE(s.ok());
    const auto back = rx::from_hst(s.value);
    REQUIRE(back.ok());
    CHECK(back.value == t);
  }
}

TEST_CASE("stamp: writes the HST date and time into a report") {
  rx::rxcod m = code_report("RGB");
  CHECK(rx::stamp(m, seed_utc) == errc::ok);
  CHECK(std::string(nmea::encode(m).view()) == "$RXCOD,101218,161229,AUVSI,RGB*49\r\n");
  CHECK(rx::stamp(m, utc(2090y / 1 / 1)) == errc::out_of_range);
  CHECK(m.date == nmea::date{2018, 12, 10});  // unchanged on error
}

// ---------------------------------------------------------------------------------------------
// scheduler

TEST_CASE("scheduler: no heartbeat until there is something to say") {
  rx::scheduler s;
  CHECK_FALSE(s.poll(seed_utc));
  CHECK(s.next_due() == rx::instant::max());
  rx::rxhrb bad = heartbeat_content();
  bad.team_id = "AUV";
  const auto refused = s.status(bad);
  CHECK(refused.ec == errc::bad_length);
  CHECK(refused.field == 7);
  CHECK_FALSE(s.status());
  CHECK_FALSE(s.poll(seed_utc));
  CHECK(s.status(heartbeat_content()).ok());
  CHECK(s.next_due() == rx::instant::min());
}

TEST_CASE("scheduler and validator: the extreme instants do not overflow") {
  // now + 1 s at instant::max() would wrap to the far past: a heartbeat on every poll.
  rx::scheduler s;
  REQUIRE(s.status(heartbeat_content()).ok());
  (void)drain(s, rx::instant::max());
  CHECK(s.next_due() == rx::instant::max());
  CHECK_FALSE(s.heartbeat_due(rx::instant::max() - 1s));
  REQUIRE(s.submit(code_report("RGB"), rx::instant::max()).accepted());
  (void)drain(s, rx::instant::max());  // sent: the next RXCOD may go 1 s later, "never"
  const auto again = s.submit(code_report("RBG"), rx::instant::max());
  CHECK(again.accepted());
  CHECK(again.release_at == rx::instant::max());

  // The validator measures time between sentences: min() to max() is held at the limit.
  rx::validator v;
  v.start(rx::instant::min());
  const std::string line = sealed("RXCOD,101218,161229,AUVSI,RGB");
  (void)v.check(line, rx::instant::min());
  const auto late = v.check(line, rx::instant::max());
  for (const auto& f : late.findings) CHECK(f.broken != rx::rule::rate);
  const auto gap = v.advance(rx::instant::max());
  REQUIRE(gap.size() == 1);
  CHECK(gap[0].elapsed == rx::instant::duration::max());
}

TEST_CASE("scheduler: heartbeat at 1 Hz, due exactly at the second, stamped in HST") {
  rx::scheduler s;
  REQUIRE(s.status(heartbeat_content()).ok());
  const auto first = drain(s, seed_utc);
  REQUIRE(first.size() == 1);
  CHECK(first[0].type == rx::report_type::heartbeat);
  CHECK(std::string(first[0].sentence.view()) ==
        "$RXHRB,101218,161229,21.31198,N,157.88972,W,AUVSI,2,1*06\r\n");
  CHECK(s.next_due() == seed_utc + 1s);
  CHECK_FALSE(s.heartbeat_due(seed_utc + 999ms));
  CHECK(drain(s, seed_utc + 999ms).empty());
  CHECK(s.heartbeat_due(seed_utc + 1s));
  const auto second = drain(s, seed_utc + 1s);
  REQUIRE(second.size() == 1);
  CHECK(std::string(second[0].sentence.view()).substr(0, 20) == "$RXHRB,101218,161230");
  CHECK(s.last_sent(rx::report_type::heartbeat) == seed_utc + 1s);
}

TEST_CASE("scheduler: a late poll delays the next heartbeat rather than sending two in 1 s") {
  rx::scheduler s;
  REQUIRE(s.status(heartbeat_content()).ok());
  REQUIRE(drain(s, seed_utc).size() == 1);
  REQUIRE(drain(s, seed_utc + 1300ms).size() == 1);
  CHECK(s.next_due() == seed_utc + 2300ms);
  CHECK(drain(s, seed_utc + 2s).empty());
  CHECK(drain(s, seed_utc + 2300ms).size() == 1);
}

TEST_CASE("scheduler: a heartbeat period below the rate limit is raised to it") {
  rx::scheduler s({.heartbeat_period = 200ms});
  CHECK(s.config().heartbeat_period == 1s);
  rx::scheduler slow({.heartbeat_period = 2s});
  REQUIRE(slow.status(heartbeat_content()).ok());
  REQUIRE(drain(slow, seed_utc).size() == 1);
  CHECK(slow.next_due() == seed_utc + 2s);
}

TEST_CASE("scheduler: task reports, one per type per second, held by default") {
  rx::scheduler s;
  REQUIRE(s.status(heartbeat_content()).ok());
  const auto a = s.submit(code_report("RGB"), seed_utc);
  CHECK(a.status == rx::submit_status::ready);
  CHECK(a.release_at == seed_utc);
  auto out = drain(s, seed_utc);
  REQUIRE(out.size() == 2);
  CHECK(out[0].type == rx::report_type::heartbeat);  // the heartbeat goes first
  CHECK(out[1].type == rx::report_type::scan_code);
  CHECK(std::string(out[1].sentence.view()) == "$RXCOD,101218,161229,AUVSI,RGB*49\r\n");

  // The same type 0.999 s later: held until a full second after the first went out.
  const auto b = s.submit(code_report("BBG"), seed_utc + 999ms);
  CHECK(b.status == rx::submit_status::held);
  CHECK(b.release_at == seed_utc + 1s);
  CHECK(s.waiting(rx::report_type::scan_code));
  // Another type is not held back by it.
  rx::rxdok dok;
  dok.team_id = "AUVSI";
  dok.shape_color = rx::color::green;
  dok.shape = rx::dock_shape::cruciform;
  CHECK(s.submit(dok, seed_utc + 999ms).status == rx::submit_status::ready);
  out = drain(s, seed_utc + 999ms);
  REQUIRE(out.size() == 1);
  CHECK(out[0].type == rx::report_type::dock);
  CHECK(std::string(out[0].sentence.view()) == "$RXDOK,101218,161229,AUVSI,G,CRUC*7A\r\n");

  // A newer report of a held type replaces the held one.
  const auto c = s.submit(code_report("GGR"), seed_utc + 999ms + 500us);
  CHECK(c.status == rx::submit_status::replaced);
  CHECK(c.release_at == seed_utc + 1s);
  CHECK(s.next_due() == seed_utc + 1s);
  out = drain(s, seed_utc + 1s);
  REQUIRE(out.size() == 2);
  CHECK(out[0].type == rx::report_type::heartbeat);
  CHECK(std::string(out[1].sentence.view()).substr(0, 31) == "$RXCOD,101218,161230,AUVSI,GGR*");
  CHECK_FALSE(s.waiting(rx::report_type::scan_code));
  CHECK(drain(s, seed_utc + 1500ms).empty());
}

TEST_CASE("scheduler: exactly one second apart is allowed") {
  rx::scheduler s;
  CHECK(s.submit(code_report("RGB"), seed_utc).status == rx::submit_status::ready);
  REQUIRE(drain(s, seed_utc).size() == 1);
  CHECK(s.submit(code_report("RGB"), seed_utc + 1s).status == rx::submit_status::ready);
  CHECK(drain(s, seed_utc + 1s).size() == 1);
}

TEST_CASE("scheduler: the refuse policy gives a report back with when it could go") {
  rx::scheduler s({.when_too_soon = rx::too_soon::refuse});
  CHECK(s.submit(code_report("RGB"), seed_utc).status == rx::submit_status::ready);
  // Waiting but not yet sent: a second one would go in the same second.
  const auto waiting = s.submit(code_report("BGR"), seed_utc);
  CHECK(waiting.status == rx::submit_status::refused);
  CHECK(waiting.release_at == seed_utc + 1s);
  REQUIRE(drain(s, seed_utc + 100ms).size() == 1);
  const auto soon = s.submit(code_report("BGR"), seed_utc + 1099ms);
  CHECK(soon.status == rx::submit_status::refused);
  CHECK(soon.release_at == seed_utc + 1100ms);
  CHECK_FALSE(soon.accepted());
  CHECK_FALSE(s.waiting(rx::report_type::scan_code));
  CHECK(drain(s, seed_utc + 1099ms).empty());
  CHECK(s.submit(code_report("BGR"), seed_utc + 1100ms).status == rx::submit_status::ready);
}

TEST_CASE("scheduler: a report that would not encode is refused with its field") {
  rx::scheduler s;
  rx::rxcod bad = code_report("RGB");
  bad.team_id = "AU";
  const auto r = s.submit(bad, seed_utc);
  CHECK(r.status == rx::submit_status::invalid);
  CHECK(r.ec == errc::bad_length);
  CHECK(r.field == 3);
  CHECK_FALSE(s.waiting(rx::report_type::scan_code));
}

TEST_CASE("scheduler: without stamping, the caller's date and time are sent") {
  rx::scheduler s({.stamp_reports = false});
  rx::rxcod m = code_report("RGB");
  m.date = {2018, 12, 10};
  m.time = {16, 12, 29, 0, 0};
  REQUIRE(s.submit(m, utc(2025y / 1 / 1)).accepted());
  const auto out = drain(s, utc(2025y / 1 / 1));
  REQUIRE(out.size() == 1);
  CHECK(std::string(out[0].sentence.view()) == "$RXCOD,101218,161229,AUVSI,RGB*49\r\n");
}

TEST_CASE("scheduler: a now that cannot be stamped uses up the slot with an error") {
  rx::scheduler s;
  REQUIRE(s.status(heartbeat_content()).ok());
  const auto out = drain(s, utc(2090y / 1 / 1));
  REQUIRE(out.size() == 1);
  CHECK(out[0].sentence.ec == errc::out_of_range);
  CHECK(s.next_due() == utc(2090y / 1 / 1) + 1s);
}

TEST_CASE("scheduler: held reports go in the order they became due") {
  rx::scheduler s;
  rx::rxdel del;
  del.team_id = "AUVSI";
  rx::rxgat gat;
  gat.team_id = "AUVSI";
  REQUIRE(s.submit(del, seed_utc).accepted());
  REQUIRE(drain(s, seed_utc).size() == 1);
  REQUIRE(s.submit(gat, seed_utc + 100ms).accepted());
  REQUIRE(drain(s, seed_utc + 100ms).size() == 1);
  CHECK(s.submit(gat, seed_utc + 200ms).release_at == seed_utc + 1100ms);
  CHECK(s.submit(del, seed_utc + 300ms).release_at == seed_utc + 1s);
  const auto out = drain(s, seed_utc + 2s);
  REQUIRE(out.size() == 2);
  CHECK(out[0].type == rx::report_type::deliver);
  CHECK(out[1].type == rx::report_type::gates);
}

// ---------------------------------------------------------------------------------------------
// validator

TEST_CASE("validator: the spec's reports, a second apart, are clean") {
  rx::validator v({.expected_team = rx::team("AUVSI"), .clock_tolerance = 5s});
  const std::string_view lines[] = {
      "$RXHRB,101218,161229,21.31198,N,157.88972,W,AUVSI,2,1*06\r\n",
      "$RXGAT,101218,161229,AUVSI,1,2,Y,RGB*25\r\n",
      "$RXCOD,101218,161229,AUVSI,RGB*49\r\n",
      "$RXDOK,101218,161229,AUVSI,R,TRIAN*28\r\n",
      "$RXDEL,101218,161229,AUVSI,R,CIRCL*32\r\n",
  };
  for (std::string_view line : lines) {
    INFO(line);
    const auto verdict = v.check(line, seed_utc + 300ms);
    CHECK(verdict.accepted);
    CHECK(rules_of(verdict.findings) == std::vector<std::string>{});
    CHECK(verdict.clean());
  }
  const auto hb = v.check(lines[0], seed_utc + 1300ms);
  CHECK(hb.clean());
  REQUIRE(std::holds_alternative<rx::rxhrb>(hb.message));
  CHECK(std::get<rx::rxhrb>(hb.message).team_id == "AUVSI"sv);
  CHECK(v.totals().lines == 6);
  CHECK(v.totals().accepted == 6);
}

// The validator is constexpr too: the bad heartbeat's six findings, at compile time.
static_assert([] {
  rx::validator v;
  const auto verdict = v.check("$RXHRB,29620,1384,0,N,0,E,USYD_ROWBOT,3,1*5e", seed_utc);
  return !verdict.accepted && verdict.findings.size() == 6 &&
         verdict.findings[0].ec == errc::checksum_mismatch &&
         verdict.findings.find(rx::rule::team_id)->field == 7;
}());

TEST_CASE("validator: the bad-on-purpose heartbeat, every error at once") {
  rx::validator v;
  const auto verdict = v.check("$RXHRB,29620,1384,0,N,0,E,USYD_ROWBOT,3,1*5e", seed_utc);
  CHECK_FALSE(verdict.accepted);
  CHECK(rules_of(verdict.findings) == std::vector<std::string>{
                                          "checksum RXHRB 0 checksum_mismatch",
                                          "checksum_lowercase RXHRB 0 ok",
                                          "unpadded RXHRB 1 bad_date",
                                          "unpadded RXHRB 2 bad_time",
                                          "team_id RXHRB 7 bad_length",
                                          "field RXHRB 8 bad_enum",
                                      });
  CHECK(verdict.findings[0].at == seed_utc);
  CHECK(v.totals().of(rx::rule::unpadded) == 2);
  CHECK(v.totals().accepted == 0);
}

TEST_CASE("validator: each field error reported on its own, not only the first") {
  rx::validator v;
  const auto verdict = v.check(sealed("RXGAT,101318,161299,AUVS,4,2,X,RGW"), seed_utc);
  CHECK_FALSE(verdict.accepted);
  CHECK(rules_of(verdict.findings) == std::vector<std::string>{
                                          "field RXGAT 1 month_out_of_range",
                                          "field RXGAT 2 second_out_of_range",
                                          "team_id RXGAT 3 bad_length",
                                          "field RXGAT 4 bad_enum",
                                          "field RXGAT 6 bad_enum",
                                          "field RXGAT 7 bad_enum",
                                      });
}

TEST_CASE("validator: checksum findings") {
  rx::validator v;
  // Lower case only: accepted, flagged.
  CHECK(checked(v, "$RXHRB,101218,161229,21.31198,N,157.88972,W,ROBO1,2,1*7f\r\n", seed_utc,
                {"checksum_lowercase RXHRB 0 ok"})
            .accepted);

  // 0x28 written as decimal 40: two digits, so it reads as a wrong hex checksum.
  CHECK_FALSE(checked(v, "$RXDOK,101218,161229,AUVSI,R,TRIAN*40\r\n", seed_utc,
                      {"checksum_decimal RXDOK 0 checksum_mismatch"})
                  .accepted);

  // 0x74 written as decimal 116: three digits, not a checksum at all; the fields still checked.
  CHECK_FALSE(checked(v, "$RXHRB,101218,161229,21.31198,N,157.88972,W,TEAM7,2,7*116\r\n",
                      seed_utc + 2s,
                      {
                          "checksum RXHRB 0 bad_checksum_format",
                          "field RXHRB 9 bad_enum",
                      })
                  .accepted);
  // A whole checksum then other characters: the checksum rule names them; fields still read.
  rx::validator fresh;  // no RXHRB before it: no rate finding
  CHECK_FALSE(checked(fresh, "$RXHRB,101218,161229,21.31198,N,157.88972,W,ROBO1,2,7*7F \r\n",
                      seed_utc + 2s,
                      {
                          "checksum RXHRB 0 trailing_characters",
                          "field RXHRB 9 bad_enum",
                      })
                  .accepted);
  // A second '*' makes the checksum text malformed; the fields before it are still read.
  checked(v, "$RXDEL,101218,161229,AUVSI,R,CIRCL*3*2\r\n", seed_utc + 2s,
          {"checksum RXDEL 0 bad_checksum_format"});
  checked(v, "$RXHRB,101218,161229,21.31198,N,157.88972,W,TEAM7,2,1*116\r\n", seed_utc + 4s,
          {"checksum_decimal RXHRB 0 bad_checksum_format"});

  CHECK_FALSE(checked(v, "$RXCOD,101218,161229,AUVSI,RGB\r\n", seed_utc,
                      {"checksum RXCOD 0 missing_checksum"})
                  .accepted);

  CHECK_FALSE(checked(v, "$RXDEL,101218,161229,AUVSI,R,CIRCL*33\r\n", seed_utc + 5s,
                      {"checksum RXDEL 0 checksum_mismatch"})
                  .accepted);
}

TEST_CASE("validator: line endings are judged only when the line has one") {
  rx::validator v;
  CHECK(checked(v, "$RXCOD,101218,161229,AUVSI,RGB*49\n", seed_utc,
                {"line_ending RXCOD 0 bad_line_ending"})
            .accepted);
  checked(v, "$RXDOK,101218,161229,AUVSI,R,TRIAN*28\r", seed_utc,
          {"line_ending RXDOK 0 bad_line_ending"});
  const auto none = v.check("$RXDEL,101218,161229,AUVSI,R,CIRCL*32", seed_utc);
  CHECK(none.clean());
}

TEST_CASE("validator: framing, unknown addresses, field counts") {
  rx::validator v({.heartbeat_gap_limit = 1h});
  CHECK_FALSE(
      checked(v, "RXCOD,101218,161229,AUVSI,RGB*49\r\n", seed_utc, {"framing  0 missing_start"})
          .accepted);
  // '!' starts encapsulation sentences (!AIVDM), not RobotX reports.
  CHECK_FALSE(
      checked(v, "!RXCOD,101218,161229,AUVSI,RGB*49\r\n", seed_utc, {"framing  0 missing_start"})
          .accepted);

  const auto other = checked(v, "$GPRMC,,V,,,,,,,,,,N*53\r\n", seed_utc,
                             {"unknown_address GPRMC 0 unknown_address"});
  CHECK_FALSE(other.accepted);
  REQUIRE(std::holds_alternative<nmea::unknown_sentence>(other.message));
  CHECK(std::get<nmea::unknown_sentence>(other.message).sentence.address == "GPRMC");

  // An extra field: the judges' decoder ignores it, the validator says so.
  CHECK(checked(v, sealed("RXCOD,101218,161229,AUVSI,RGB,"), seed_utc + 1s,
                {"field_count RXCOD 5 too_many_fields"})
            .accepted);

  // A trailing optional field left out: decoded, but the sentence is short.
  CHECK(checked(v, sealed("RXHRB,101218,161229,21.31198,N,157.88972,W,AUVSI,2"), seed_utc + 2s,
                {"field_count RXHRB 9 too_few_fields"})
            .accepted);

  // A required field missing: reported once, where the sentence ends.
  CHECK_FALSE(
      checked(v, sealed("RXDOK,101218"), seed_utc + 3s, {"field_count RXDOK 2 too_few_fields"})
          .accepted);
}

TEST_CASE("validator: team ids") {
  rx::validator v({.expected_team = rx::team("AUVSI")});
  CHECK(checked(v, sealed("RXCOD,101218,161229,ROBOT,RGB"), seed_utc, {"team_mismatch RXCOD 3 ok"})
            .accepted);
  checked(v, sealed("RXHRB,101218,161229,,,,,,2,1"), seed_utc, {"team_id RXHRB 7 missing_field"});
  checked(v, sealed("RXDOK,101218,161229,AUVSI1,R,TRIAN"), seed_utc,
          {"team_id RXDOK 3 bad_length"});
}

TEST_CASE("validator: rate per message type, 1 Hz exactly at the boundary") {
  rx::validator v;
  const std::string cod = sealed("RXCOD,101218,161229,AUVSI,RGB");
  CHECK(v.check(cod, seed_utc).clean());
  const auto soon = v.check(cod, seed_utc + 999ms);
  CHECK(soon.accepted);  // the rate is a rule of the link, not of the sentence
  REQUIRE(rules_of(soon.findings) == std::vector<std::string>{"rate RXCOD 0 ok"});
  CHECK(soon.findings[0].elapsed == 999ms);
  // Measured from the previous transmission, so 1 s after the last one is fine again.
  CHECK(v.check(cod, seed_utc + 1999ms).clean());
  // A different type in the same millisecond is not a rate problem.
  CHECK(v.check(sealed("RXDOK,101218,161229,AUVSI,R,TRIAN"), seed_utc + 1999ms).clean());
  // Rejected sentences count too: they were sent.
  const auto bad = v.check("$RXCOD,101218,161229,AUVSI,RGB*00", seed_utc + 2500ms);
  CHECK(rules_of(bad.findings) == std::vector<std::string>{
                                      "checksum RXCOD 0 checksum_mismatch",
                                      "rate RXCOD 0 ok",
                                  });
  CHECK(v.totals().of(rx::rule::rate) == 2);
}

TEST_CASE("validator: heartbeat gap over the limit, reported once") {
  const std::string hb = sealed("RXHRB,101218,161229,21.31198,N,157.88972,W,AUVSI,2,1");
  rx::validator v;  // limit 1.5 s
  CHECK(v.check(hb, seed_utc).clean());
  CHECK(v.check(hb, seed_utc + 1s).clean());
  CHECK(v.check(hb, seed_utc + 2500ms).clean());  // 1.5 s: not over the limit
  const auto late = v.check(hb, seed_utc + 4501ms);
  REQUIRE(rules_of(late.findings) == std::vector<std::string>{"heartbeat_gap RXHRB 0 ok"});
  CHECK(late.findings[0].elapsed == 2001ms);

  // Live: advance() reports an open gap once, and the heartbeat that closes it does not again.
  CHECK(v.advance(seed_utc + 5s).empty());
  const auto open = v.advance(seed_utc + 6100ms);
  REQUIRE(open.size() == 1);
  CHECK(open[0].broken == rx::rule::heartbeat_gap);
  CHECK(open[0].elapsed == 1599ms);
  CHECK(v.advance(seed_utc + 7s).empty());
  CHECK(v.check(hb, seed_utc + 8s).clean());
  CHECK(v.totals().of(rx::rule::heartbeat_gap) == 2);

  // Other reports do not close a gap.
  CHECK(v.check(sealed("RXCOD,101218,161229,AUVSI,RGB"), seed_utc + 9s).clean());
  const auto closed = v.check(hb, seed_utc + 10s);
  REQUIRE(closed.findings.size() == 1);
  CHECK(closed.findings[0].elapsed == 2s);

  // A rejected heartbeat is not a heartbeat to the judges.
  CHECK_FALSE(v.check("$RXHRB,101218,161229,,,,,AUVSI,2,1*00", seed_utc + 11s).accepted);
  const auto after = v.check(hb, seed_utc + 12s);
  CHECK(after.findings.find(rx::rule::heartbeat_gap) != nullptr);
}

TEST_CASE("validator: a session with no heartbeat at all") {
  rx::validator v({.heartbeat_gap_limit = 3s});
  v.start(seed_utc);
  CHECK(v.advance(seed_utc + 3s).empty());
  const auto end = v.finish(seed_utc + 10s);
  REQUIRE(end.size() == 1);
  CHECK(end[0].elapsed == 10s);
  CHECK(end[0].address == "RXHRB"sv);
}

TEST_CASE("validator: clock skew, e.g. a report stamped in UTC") {
  rx::validator v({.clock_tolerance = 5s});
  // 02:12:29 written as if it were HST: 10 h behind the arrival time.
  const auto utc_stamped = v.check(sealed("RXCOD,111218,021229,AUVSI,RGB"), seed_utc);
  CHECK(utc_stamped.accepted);
  REQUIRE(rules_of(utc_stamped.findings) == std::vector<std::string>{"clock_skew RXCOD 2 ok"});
  CHECK(utc_stamped.findings[0].elapsed == 10h);
  CHECK(v.check(sealed("RXDOK,101218,161234,AUVSI,R,TRIAN"), seed_utc).clean());  // +5 s
  CHECK(v.check(sealed("RXDEL,101218,161235,AUVSI,R,TRIAN"), seed_utc)
            .findings.count(rx::rule::clock_skew) == 1);
}

TEST_CASE("validator: hemisphere letters that flip far from the equator") {
  rx::validator v;
  CHECK(v.check(sealed("RXHRB,101218,161229,21.31198,N,157.88972,W,AUVSI,2,1"), seed_utc).clean());
  const auto flip =
      v.check(sealed("RXHRB,101218,161230,21.31198,S,157.88972,E,AUVSI,2,1"), seed_utc + 1s);
  CHECK(flip.accepted);
  CHECK(rules_of(flip.findings) == std::vector<std::string>{
                                       "hemisphere_flip RXHRB 4 bad_hemisphere",
                                       "hemisphere_flip RXHRB 6 bad_hemisphere",
                                   });
  // Near the equator a change of letter is a crossing, not an error.
  rx::validator w;
  CHECK(w.check(sealed("RXHRB,101218,161229,0.00010,N,0.5,E,AUVSI,2,1"), seed_utc).clean());
  CHECK(w.check(sealed("RXHRB,101218,161230,0.00010,S,0.5,W,AUVSI,2,1"), seed_utc + 1s).clean());
}

TEST_CASE("scheduler output passes the validator: 20 simulated seconds, reports every 300 ms") {
  rx::scheduler s;
  rx::validator v({.expected_team = rx::team("AUVSI"), .clock_tolerance = 1s});
  REQUIRE(s.status(heartbeat_content()).ok());
  const char* patterns[] = {"RGB", "BGR", "GRB"};
  int sent = 0;
  int heartbeats = 0;
  for (int tick = 0; tick <= 2000; ++tick) {  // a 10 ms loop
    const rx::instant now = seed_utc + tick * 10ms;
    if (tick % 30 == 0) {
      const auto r = s.submit(code_report(patterns[tick / 30 % 3]), now);
      CHECK(r.accepted());
      rx::rxdok dok;
      dok.team_id = "AUVSI";
      dok.shape = rx::dock_shape::circle;
      CHECK(s.submit(dok, now).accepted());
    }
    for (const auto& out : drain(s, now)) {
      REQUIRE(static_cast<bool>(out.sentence));
      const auto verdict = v.check(out.sentence.view(), now);
      INFO(std::string(out.sentence.view()));
      CHECK(rules_of(verdict.findings) == std::vector<std::string>{});
      CHECK(verdict.accepted);
      ++sent;
      heartbeats += out.type == rx::report_type::heartbeat ? 1 : 0;
    }
  }
  CHECK(heartbeats == 21);  // t = 0, 1, ..., 20 s
  CHECK(sent == 21 * 3);    // and one RXCOD and one RXDOK each second
  CHECK(v.finish(seed_utc + 20s).empty());
}
