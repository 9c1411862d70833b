// SPDX-License-Identifier: BSL-1.0
#pragma once
// Tracks for seawire-decode --format geojson and --format svg: every message that carries a
// position (a latitude and a longitude field, as the walk over its fields says: walk.hpp) adds a
// vertex to the track of its source; the track is written at the end, as GeoJSON (RFC 7946) or as
// an SVG picture. Each field's value is its JSON text.
//
// A source is the message type ("CPNVG", "GPRMC", "AB00"), or type and team for messages that
// name one ("RXHRB AUVSI"). A change of state between consecutive positions of a source (an enum
// or flag such as the RobotX system mode, the RMC status, a frame's fix quality) is an event:
// a GeoJSON Point where it happened.

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "io.hpp"
#include "seawire/anello/frame_json.hpp"
#include "seawire/nmea/json.hpp"
#include "seawire/nmea2000/json.hpp"
#include "seawire/walk.hpp"

namespace seawire::tools {

/// One field of a message as its JSON object has it: key, value text, whether it is a state
/// (an enum, a flag or a code) whose changes are events, and which axis of a position it holds.
struct json_field {
  std::string_view key;
  std::string_view value;
  bool state = false;
  position_axis axis = position_axis::none;
};

namespace tracked {
// Whether a field's values are states whose changes along a track are events: enums and flags
// of a sentence, lookups and flag sets of a PGN, the frame's codes (fix quality).
template <class V>
struct is_state : std::bool_constant<std::is_same_v<V, bool> || nmea::char_enum_like<V> ||
                                     nmea::word_enum_like<V>> {};
template <class V>
struct is_state<std::optional<V>> : is_state<V> {};
template <class E, unsigned B>
struct is_state<nmea2000::lookup<E, B>> : std::true_type {};
template <class E, unsigned B>
struct is_state<nmea2000::flags<E, B>> : std::true_type {};

template <class View>
constexpr bool state_field() {
  if constexpr (View::kind == wire_kind::anello_frame) {
    return std::is_integral_v<typename std::remove_cvref_t<decltype(View::desc)>::value_type>;
  } else {
    return is_state<typename View::value_type>::value;
  }
}
}  // namespace tracked

/// A JSON string's content without its quotes, still escaped (as it goes back into JSON).
inline std::string_view unquoted(std::string_view v) {
  if (v.size() >= 2 && v.front() == '"' && v.back() == '"') return v.substr(1, v.size() - 2);
  return v;
}

/// Escaped JSON string content as the text it stands for: \" \\ \/ \n \r \t and \u00XX (the
/// library writes no other escapes).
inline std::string unescaped(std::string_view v) {
  std::string out;
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (v[i] != '\\' || i + 1 == v.size()) {
      out += v[i];
      continue;
    }
    const char e = v[++i];
    if (e == 'n') {
      out += '\n';
    } else if (e == 'r') {
      out += '\r';
    } else if (e == 't') {
      out += '\t';
    } else if (e == 'u' && i + 4 < v.size()) {
      unsigned code = 0;
      std::from_chars(v.data() + i + 1, v.data() + i + 5, code, 16);
      out += static_cast<char>(code & 0xFFU);
      i += 4;
    } else {
      out += e;
    }
  }
  return out;
}

class tracks {
 public:
  /// Whether messages of type M carry a position: a latitude and a longitude field.
  template <class M>
  static constexpr bool has_position = [] {
    bool lat = false;
    bool lon = false;
    visit_layout<M>([&](auto f) {
      lat = lat || f.axis == position_axis::latitude;
      lon = lon || f.axis == position_axis::longitude;
    });
    return lat && lon;
  }();

  /// Adds a message of any wire, of JSON type `type` ("CPNVG", "GPRMC", "AB00"): its fields as
  /// the walk gives them (walk.hpp), each value as its JSON text. Messages without a position
  /// (or with a blank one) are not part of any track.
  template <class M>
  void add(std::string_view type, const M& msg) {
    if constexpr (has_position<M>) {
      text_.clear();
      ends_.clear();
      fields_.clear();
      visit_fields(msg, [&](const auto& f) {
        put_field_value<nmea::json_style::json>(*this, f);
        ends_.push_back(text_.size());
        fields_.push_back(
            {f.key, {}, tracked::state_field<std::remove_cvref_t<decltype(f)>>(), f.axis});
      });
      std::size_t start = 0;
      for (std::size_t i = 0; i < fields_.size(); ++i) {
        fields_[i].value = std::string_view(text_).substr(start, ends_[i] - start);
        start = ends_[i];
      }
      add_fields(type, fields_);
    }
  }

  /// The sink the values are written to (for add).
  void put(char c) { text_ += c; }
  void put(std::string_view v) { text_ += v; }

  /// Adds a message given as its fields' JSON text (the position's by their axis).
  void add_fields(std::string_view type, std::span<const json_field> fields) {
    const json_field* lat = nullptr;
    const json_field* lon = nullptr;
    std::string_view team;
    for (const json_field& f : fields) {
      if (f.axis == position_axis::latitude && lat == nullptr) lat = &f;
      if (f.axis == position_axis::longitude && lon == nullptr) lon = &f;
      if (f.key == "team_id") team = unquoted(f.value);
    }
    if (lat == nullptr || lon == nullptr || lat->value == "null" || lon->value == "null") return;
    std::string name(type);
    if (!team.empty()) name.append(" ").append(team);
    auto [it, is_new] = sources_.try_emplace(name);
    source& s = it->second;
    if (is_new) {
      s.index = sources_.size() - 1;
      s.name = name;
      s.type = type;
    }
    s.points.emplace_back(number(lon->value), number(lat->value));
    if (s.points.size() > 1) s.coordinates += ',';
    s.coordinates.append("[").append(lon->value).append(",").append(lat->value).append("]");

    // Per-vertex properties: every member but the type and the position, in field order.
    std::size_t k = 0;
    std::string changes;
    std::string previous;
    for (const json_field& f : fields) {
      if (&f == lat || &f == lon) continue;
      if (k == s.columns.size()) s.columns.push_back({std::string(f.key), {}, {}});
      column& c = s.columns[k++];
      if (!c.values.empty()) c.values += ',';
      c.values += f.value;
      // A state that was or is blank says nothing about a change (an RMC without the mode
      // field between two with it has not changed mode).
      if (f.state && f.value != "null") {
        if (!c.last.empty() && c.last != f.value) {
          changes.append(changes.empty() ? "\"" : ",\"").append(f.key).append("\"");
          previous.append(previous.empty() ? "\"" : ",\"").append(f.key).append("\":");
          previous.append(c.last);
        }
        c.last = f.value;
      }
    }
    if (!changes.empty()) {
      // An event: a Point with the message's own values, what changed, and what it was.
      std::string& e = events_;
      e.append(",\n{\"type\":\"Feature\",\"geometry\":{\"type\":\"Point\",\"coordinates\":[");
      e.append(lon->value).append(",").append(lat->value).append("]},\"properties\":{");
      e.append("\"source\":\"").append(name).append("\",\"event\":\"state change\",\"changed\":[");
      e.append(changes).append("],\"previous\":{").append(previous).append("}");
      for (const json_field& f : fields) {
        if (&f == lat || &f == lon) continue;
        e.append(",\"").append(f.key).append("\":").append(f.value);
      }
      e.append("}}");
    }
  }

  [[nodiscard]] std::size_t source_count() const { return sources_.size(); }

  /// A GeoJSON FeatureCollection: per source, a LineString of its positions whose properties
  /// are the source, the message type, the vertex count and, per field, the array of each
  /// vertex's value (a source with one position: a Point, with the values themselves); then the
  /// events' Points.
  void write_geojson(output& out) const {
    out.put("{\"type\":\"FeatureCollection\",\"features\":[");
    bool first = true;
    for (const source* s : in_order()) {
      const bool single = s->points.size() == 1;
      out.put(first ? "\n" : ",\n");
      first = false;
      out.put("{\"type\":\"Feature\",\"geometry\":{\"type\":\"");
      out.put(single ? "Point" : "LineString");
      out.put("\",\"coordinates\":");
      if (single) {
        out.put(s->coordinates);
      } else {
        out.put('[');
        out.put(s->coordinates);
        out.put(']');
      }
      out.put("},\"properties\":{\"source\":\"");
      out.put(s->name);
      out.put("\",\"message_type\":\"");
      out.put(s->type);
      out.put("\",\"points\":");
      out.put(std::to_string(s->points.size()));
      for (const column& c : s->columns) {
        out.put(",\"");
        out.put(c.key);
        out.put("\":");
        if (!single) out.put('[');
        out.put(c.values);
        if (!single) out.put(']');
      }
      out.put("}}");
    }
    if (!events_.empty()) out.put(first ? std::string_view(events_).substr(1) : events_);
    out.put("\n]}\n");
  }

  /// An SVG picture of the tracks, 800 x 600 px: each source's polyline in its own colour, a
  /// filled circle at its start and a filled square at its end, a scale bar in metres and a
  /// legend. Equirectangular around the mean latitude of all positions (x = R lon cos(lat0),
  /// y = R lat, R = 6371008.8 m), scaled alike both ways to fit the plot area (40,40)-(760,520)
  /// and centred in it, north up.
  void write_svg(output& out) const {
    constexpr double width = 800, height = 600, left = 40, top = 40, right = 760, bottom = 520;
    constexpr double earth_radius_m = 6371008.8;
    constexpr double rad = 3.14159265358979323846 / 180.0;
    double lat_sum = 0;
    std::size_t n = 0;
    for (const auto& [name, s] : sources_) {
      for (const auto& [x, y] : s.points) lat_sum += y;
      n += s.points.size();
    }
    const double k = n == 0 ? 0 : earth_radius_m * rad;
    const double cos0 = n == 0 ? 1 : std::cos(lat_sum / static_cast<double>(n) * rad);
    double x0 = 0, x1 = 0, y0 = 0, y1 = 0;
    bool any = false;
    for (const auto& [name, s] : sources_) {
      for (const auto& [lon, lat] : s.points) {
        const double x = k * lon * cos0, y = k * lat;
        x0 = any ? std::min(x0, x) : x;
        x1 = any ? std::max(x1, x) : x;
        y0 = any ? std::min(y0, y) : y;
        y1 = any ? std::max(y1, y) : y;
        any = true;
      }
    }
    const double dx = x1 - x0, dy = y1 - y0;
    double scale = 1;  // px per metre
    if (dx > 0 || dy > 0) {
      scale = std::min(dx > 0 ? (right - left) / dx : 1e300, dy > 0 ? (bottom - top) / dy : 1e300);
    }
    const double cx = (left + right) / 2, cy = (top + bottom) / 2;
    const double mx = (x0 + x1) / 2, my = (y0 + y1) / 2;
    char buf[160];
    const auto put = [&](const char* fmt, auto... args) {
      const int len = std::snprintf(buf, sizeof buf, fmt, args...);
      if (len > 0)
        out.put(std::string_view(buf, std::min(static_cast<std::size_t>(len), sizeof buf - 1)));
    };
    const auto px = [&](double lon) { return cx + (k * lon * cos0 - mx) * scale; };
    const auto py = [&](double lat) { return cy - (k * lat - my) * scale; };

    out.put("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    put("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" "
        "viewBox=\"0 0 %.0f %.0f\" font-family=\"sans-serif\" font-size=\"13\">\n",
        width, height, width, height);
    put("<rect width=\"%.0f\" height=\"%.0f\" fill=\"#ffffff\"/>\n", width, height);
    put("<text x=\"%.0f\" y=\"24\">seawire-decode: %zu source%s, %zu position%s</text>\n", left,
        sources_.size(), sources_.size() == 1 ? "" : "s", n, n == 1 ? "" : "s");
    const std::vector<const source*> order = in_order();
    for (const source* s : order) {
      const char* colour = palette[s->index % palette.size()];
      out.put("<g><title>");
      put_xml(out, unescaped(s->name));
      out.put("</title>\n");
      if (s->points.size() > 1) {
        put("<polyline fill=\"none\" stroke=\"%s\" stroke-width=\"2\" "
            "stroke-linejoin=\"round\" points=\"",
            colour);
        for (std::size_t i = 0; i < s->points.size(); ++i)
          put(i == 0 ? "%.1f,%.1f" : " %.1f,%.1f", px(s->points[i].first), py(s->points[i].second));
        out.put("\"/>\n");
      }
      const auto& [first_lon, first_lat] = s->points.front();
      const auto& [last_lon, last_lat] = s->points.back();
      put("<circle cx=\"%.1f\" cy=\"%.1f\" r=\"6\" fill=\"%s\" stroke=\"#000000\"/>\n",
          px(first_lon), py(first_lat), colour);
      put("<rect x=\"%.1f\" y=\"%.1f\" width=\"10\" height=\"10\" fill=\"%s\" "
          "stroke=\"#000000\"/>\n",
          px(last_lon) - 5, py(last_lat) - 5, colour);
      out.put("</g>\n");
    }
    // Scale bar: the longest 1, 2 or 5 x 10^n metres no longer than a quarter of the plot.
    if (any) {
      const double max_m = (right - left) / 4 / scale;
      double bar = std::pow(10.0, std::floor(std::log10(max_m)));
      if (5 * bar <= max_m) {
        bar *= 5;
      } else if (2 * bar <= max_m) {
        bar *= 2;
      }
      const double len = bar * scale, y = 560;
      put("<path d=\"M%.0f %.0fv6h%.1fv-6\" fill=\"none\" stroke=\"#000000\" "
          "stroke-width=\"2\"/>\n",
          left, y - 6, len);
      if (bar >= 1000) {
        put("<text x=\"%.0f\" y=\"%.0f\">%g km</text>\n", left, y + 20, bar / 1000);
      } else {
        put("<text x=\"%.0f\" y=\"%.0f\">%g m</text>\n", left, y + 20, bar);
      }
    }
    // Legend: a swatch and the name of each source (the first eight), then start and end.
    double lx = 260;
    double ly = 548;
    for (std::size_t i = 0; i < order.size() && i < 8; ++i) {
      const double x = lx + static_cast<double>(i % 2) * 250;
      const double y = ly + static_cast<double>(i / 2) * 16 - (order.size() > 2 ? 8 : 0);
      put("<path d=\"M%.0f %.0fh24\" stroke=\"%s\" stroke-width=\"4\"/>\n", x, y - 4,
          palette[order[i]->index % palette.size()]);
      put("<text x=\"%.0f\" y=\"%.0f\">", x + 30, y);
      put_xml(out, unescaped(order[i]->name));
      out.put("</text>\n");
    }
    if (order.size() > 8)
      put("<text x=\"%.0f\" y=\"594\">and %zu more</text>\n", lx, order.size() - 8);
    put("<text x=\"%.0f\" y=\"24\" text-anchor=\"end\">&#9679; start  &#9632; end</text>\n", right);
    out.put("</svg>\n");
  }

 private:
  struct column {
    std::string key;
    std::string values;  // comma-separated JSON values, one per vertex
    std::string last;    // the last value of a state column
  };
  struct source {
    std::size_t index = 0;  // order of first appearance
    std::string name;
    std::string type;
    std::string coordinates;                        // "[lon,lat],[lon,lat]..."
    std::vector<std::pair<double, double>> points;  // (longitude, latitude)
    std::vector<column> columns;
  };

  static double number(std::string_view text) {
    double v = 0;
    std::from_chars(text.data(), text.data() + text.size(), v);
    return v;
  }

  [[nodiscard]] std::vector<const source*> in_order() const {
    std::vector<const source*> v(sources_.size());
    for (const auto& [name, s] : sources_) v[s.index] = &s;
    return v;
  }

  // Ten colours that stay apart from each other and from the white ground.
  static constexpr std::array<const char*, 10> palette = {
      "#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e",
      "#8c564b", "#e377c2", "#17becf", "#7f7f7f", "#bcbd22"};

  // Text in XML: the five special characters escaped.
  static void put_xml(output& out, std::string_view text) {
    for (const char c : text) {
      switch (c) {
        case '<': out.put("&lt;"); break;
        case '>': out.put("&gt;"); break;
        case '&': out.put("&amp;"); break;
        case '"': out.put("&quot;"); break;
        case '\'': out.put("&apos;"); break;
        default: {
          // XML 1.0 has no control characters; bytes above ASCII would need an encoding.
          const auto u = static_cast<unsigned char>(c);
          out.put(u < 0x20 || u >= 0x7F ? '?' : c);
        }
      }
    }
  }

  std::map<std::string, source, std::less<>> sources_;
  std::string text_;                // add's values, one after the other
  std::vector<std::size_t> ends_;   // where each ends in text_
  std::vector<json_field> fields_;  // add's fields
  std::string events_;              // ",\n{Feature}" per event
};

}  // namespace seawire::tools
