// SPDX-License-Identifier: BSL-1.0
// A codec that says its scan() refuses a blank field (scan_refuses_blank) has its fields scanned
// before they are tested for a blank: the claim is checked where a message decodes, by running
// the scanner on blank fields, and a scanner that takes one does not compile. Each ctest case
// compiles this file with one CASE defined and expects the compiler's message; CASE ok must
// compile.
#include <optional>
#include <string_view>

#include "seawire/nmea/message.hpp"
#include "seawire/nmea/one_pass.hpp"

namespace own {
/// A bearing, "[degrees],T|M": a blank number beside its letter is a bearing without a value.
struct bearing {
  std::optional<seawire::nmea::decimal> degrees;
  char reference = 'T';
};
}  // namespace own

template <>
struct seawire::nmea::codec<own::bearing> {
  static constexpr unsigned width = 2;
  static constexpr std::size_t max_chars = 24;
  static constexpr bool allows_blank = false;
  static constexpr bool scan_refuses_blank = true;
  // Only what the claim is checked against matters here: the general path's reader and the
  // writer are the least a codec has (tests/one_pass_test.cpp decodes with a whole one).
  static constexpr errc read(field_reader& r, own::bearing&) noexcept {
    (void)r.take();
    (void)r.take();
    return errc::ok;
  }
  static constexpr errc check(const own::bearing&) noexcept { return errc::ok; }
  static constexpr void write(writer& w, const own::bearing&) noexcept { w.next_field(); }
  static constexpr const char* scan(const char* p, const char* end, own::bearing& v) noexcept {
    v.degrees.reset();
#if defined(CASE_ok)
    if (p == end || *p == ',') return nullptr;  // a blank number: left to the general path
#endif
    if (p != end && *p != ',') {
      decimal d;
      p = detail::scan_decimal(p, d);
      if (p == nullptr) return nullptr;
      v.degrees = d;
    }
    if (p == end || *p != ',' || (p[1] != 'T' && p[1] != 'M')) return nullptr;
    v.reference = p[1];
    return p + 2;
  }
};

namespace own {
struct course {
  std::optional<bearing> heading;
  static constexpr auto nmea =
      seawire::nmea::sentence<"PXYZC">(seawire::nmea::field<&course::heading>("heading"));
};
}  // namespace own

int main(int argc, char** argv) {
  const auto r = seawire::nmea::decode<own::course>(std::string_view(argc > 1 ? argv[1] : ""));
  return r.ok() ? 0 : 1;
}
