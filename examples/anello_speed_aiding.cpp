// SPDX-License-Identifier: BSL-1.0
// Speed aiding for the ANELLO Maritime INS: what a USV computer writes to the INS's NMEA input
// port (RS-232-2) from the values its own software holds in SI units. Prints each sentence to
// stdout, then decodes it back the way the INS reads it.
//
//   seawire_anello_speed_aiding            built-in values
//   seawire_anello_speed_aiding 2.4 87.3   speed through water (m/s) and heading (deg true)

#include <seawire/anello/inputs.hpp>

#include <cstdio>
#include <cstdlib>
#include <string_view>
#include <type_traits>
#include <variant>

namespace {

using namespace seawire;

int len(std::string_view s) { return static_cast<int>(s.size()); }

void refused(std::string_view what, errc ec, unsigned field) {
  std::printf("%-10.*s refused: %.*s (field %u)\n", len(what), what.data(), len(message(ec)),
              message(ec).data(), field);
}

template <std::size_t N>
void show(std::string_view what, const nmea::sentence_buffer<N>& out) {
  if (!out) return refused(what, out.ec, out.field);
  // The sentence ends in CR LF: print it without them.
  const std::string_view s = out.view().substr(0, out.view().size() - 2);
  std::printf("%-10.*s %.*s\n", len(what), what.data(), len(s), s.data());
}

/// Decode as the INS would, and say what came out.
bool read_back(std::string_view line) {
  const auto r = anello::decode_input(line);
  if (!r) {
    std::printf("  decode failed: %.*s at field %u\n", len(message(r.ec)), message(r.ec).data(),
                static_cast<unsigned>(r.field));
    return false;
  }
  std::visit(
      [](const auto& m) {
        using T = std::decay_t<decltype(m)>;
        if constexpr (std::is_same_v<T, standard::vhw>) {
          std::printf("  VHW: heading %.1f deg true, %.3f m/s through the water\n",
                      m.heading_true_deg ? m.heading_true_deg->to_double() : -1.0,
                      anello::speed_through_water_mps(m).value_or(-1.0));
        } else if constexpr (std::is_same_v<T, standard::vbw>) {
          std::printf("  VBW: water %.2f kn ahead, %.2f kn to starboard, status %c\n",
                      m.longitudinal_water_knots.value_or(nmea::decimal{}).to_double(),
                      m.transverse_water_knots.value_or(nmea::decimal{}).to_double(),
                      m.water_status ? static_cast<char>(*m.water_status) : '-');
        } else if constexpr (std::is_same_v<T, anello::papgpsctrl>) {
          std::printf("  PAPGPSCTRL: %s\n",
                      m.control == anello::gps_control::use ? "use GPS" : "do not use GPS");
        } else {
          std::printf("  something else\n");
        }
      },
      r.value);
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  double speed_mps = 2.4;
  double heading_deg = 87.3;
  if (argc == 3) {
    speed_mps = std::strtod(argv[1], nullptr);
    heading_deg = std::strtod(argv[2], nullptr);
  }

  // VHW: heading and speed through water; knots and km/h both come from the m/s value.
  anello::vhw_si vhw_in;
  vhw_in.heading_true_deg = heading_deg;
  vhw_in.speed_mps = speed_mps;
  const auto vhw = anello::make_vhw(vhw_in);
  if (!vhw) {
    refused("VHW", vhw.ec, vhw.field);
    return 1;
  }

  // VBW: the same speed along the hull, with a little leeway to port; no ground track, so the
  // ground pair goes out blank with status V.
  anello::vbw_si vbw_in;
  vbw_in.longitudinal_water_mps = speed_mps;
  vbw_in.transverse_water_mps = -0.05;
  const auto vbw = anello::make_vbw(vbw_in);
  if (!vbw) {
    refused("VBW", vbw.ec, vbw.field);
    return 1;
  }

  // encode() sizes each buffer for its message (VBW's can be longer than VHW's), so each line
  // has its own type.
  bool ok = true;
  const auto send = [&ok](std::string_view name, const auto& line) {
    show(name, line);
    ok = line && read_back(line.view()) && ok;
  };
  send("VHW", nmea::encode(vhw.value));
  send("VBW", nmea::encode(vbw.value));
  send("PAPGPSCTRL", nmea::encode(anello::papgpsctrl{anello::gps_control::use}));
  return ok ? 0 : 1;
}
