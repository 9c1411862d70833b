// SPDX-License-Identifier: BSL-1.0
#pragma once
// Error codes and result<T>: how every seawire decoder and encoder reports failure.
// No exceptions: a call returns its value together with an errc and the place it went wrong.

#include <cstdint>
#include <string_view>

namespace seawire {

/// Why a decode or encode failed. Values are stable; `name()` gives the identifier as text.
enum class errc : std::uint8_t {
  ok = 0,  ///< no error
  // -- sentence framing --
  empty_input,          ///< nothing to decode
  missing_start,        ///< the line does not begin with '$' (or '!')
  bad_address,          ///< the address is empty, too long, or not upper-case letters/digits
  bad_character,        ///< a byte outside printable ASCII 0x20..0x7E, or a reserved '$' inside
  missing_checksum,     ///< the policy requires a checksum and none was sent
  bad_checksum_format,  ///< the hex digits after '*' are not two (or lower-case when refused)
  checksum_mismatch,    ///< the checksum does not match the XOR of the sentence
  bad_line_ending,      ///< the line does not end in CR LF where the policy requires it
  too_long,             ///< the sentence is longer than the policy's maximum length
  // -- message selection --
  unknown_address,  ///< no message of the requested set has this address
  wrong_address,    ///< the sentence is not the message that was asked for
  // -- field layout --
  too_few_fields,   ///< the sentence ends before a required field
  too_many_fields,  ///< extra trailing fields and the policy does not allow them
  missing_field,    ///< a required field is blank
  // -- field values --
  bad_number,           ///< not a number: stray characters, exponent, lone sign or point
  number_too_long,      ///< more digits than the codec holds (19 significant digits)
  out_of_range,         ///< a number outside the range the spec allows for this field
  bad_time,             ///< not hhmmss[.f...]
  hour_out_of_range,    ///< hour >= 24
  minute_out_of_range,  ///< minute >= 60 (in a time, or the minutes of a position)
  second_out_of_range,  ///< second >= 60 (60 only at 23:59:60, a leap second)
  bad_date,             ///< not ddmmyy
  month_out_of_range,   ///< month 0 or > 12
  day_out_of_range,     ///< day 0 or past the end of its month
  bad_latitude,         ///< latitude not DDMM.m..., or above 90 degrees
  bad_longitude,        ///< longitude not DDDMM.m..., or above 180 degrees
  bad_hemisphere,       ///< hemisphere letter blank, or other than N/S (lat.) or E/W (long.)
  bad_enum,             ///< a letter or word that is not one of the field's values
  bad_flag,             ///< a flag that is not 0 or 1
  bad_unit,             ///< a unit letter other than the one the field requires
  bad_text,             ///< text with a character the field may not carry
  text_too_long,        ///< text longer than the field's capacity (and no declared length)
  bad_length,           ///< wrong length: a field or frame, or text outside its declared length
  // -- encoding --
  not_finite,        ///< NaN or infinity given to an encoder
  value_too_large,   ///< a value that does not fit its wire field
  buffer_too_small,  ///< the output buffer cannot hold the sentence or frame
  // -- binary frames --
  bad_frame_id,  ///< a binary frame whose identifier is not the expected one
  crc_mismatch,  ///< a binary frame whose CRC does not match its payload
  truncated,     ///< input ends before the frame or message does
  // -- added later (values are stable, so new ones go last) --
  bad_variation,            ///< magnetic variation not an unsigned number of degrees
  bad_variation_direction,  ///< magnetic variation letter other than E or W
  variation_out_of_range,   ///< magnetic variation to send beyond 0..180 degrees
  // -- NMEA 2000 --
  bad_can_id,          ///< not a 29-bit identifier, or fields no identifier can carry
  bad_log_line,        ///< a CAN log line of no known format, or malformed in its format
  unknown_log_format,  ///< a log's format header names a format seawire does not read
  // -- sentence framing, added later --
  trailing_characters,  ///< "*hh" then a character that is no hex digit, before the line ending
};

/// The identifier of an errc as text ("checksum_mismatch"), for logs and JSON.
[[nodiscard]] constexpr std::string_view name(errc e) noexcept {
  switch (e) {
    case errc::ok: return "ok";
    case errc::empty_input: return "empty_input";
    case errc::missing_start: return "missing_start";
    case errc::bad_address: return "bad_address";
    case errc::bad_character: return "bad_character";
    case errc::missing_checksum: return "missing_checksum";
    case errc::bad_checksum_format: return "bad_checksum_format";
    case errc::checksum_mismatch: return "checksum_mismatch";
    case errc::bad_line_ending: return "bad_line_ending";
    case errc::too_long: return "too_long";
    case errc::unknown_address: return "unknown_address";
    case errc::wrong_address: return "wrong_address";
    case errc::too_few_fields: return "too_few_fields";
    case errc::too_many_fields: return "too_many_fields";
    case errc::missing_field: return "missing_field";
    case errc::bad_number: return "bad_number";
    case errc::number_too_long: return "number_too_long";
    case errc::out_of_range: return "out_of_range";
    case errc::bad_time: return "bad_time";
    case errc::hour_out_of_range: return "hour_out_of_range";
    case errc::minute_out_of_range: return "minute_out_of_range";
    case errc::second_out_of_range: return "second_out_of_range";
    case errc::bad_date: return "bad_date";
    case errc::month_out_of_range: return "month_out_of_range";
    case errc::day_out_of_range: return "day_out_of_range";
    case errc::bad_latitude: return "bad_latitude";
    case errc::bad_longitude: return "bad_longitude";
    case errc::bad_hemisphere: return "bad_hemisphere";
    case errc::bad_enum: return "bad_enum";
    case errc::bad_flag: return "bad_flag";
    case errc::bad_unit: return "bad_unit";
    case errc::bad_text: return "bad_text";
    case errc::text_too_long: return "text_too_long";
    case errc::bad_length: return "bad_length";
    case errc::not_finite: return "not_finite";
    case errc::value_too_large: return "value_too_large";
    case errc::buffer_too_small: return "buffer_too_small";
    case errc::bad_frame_id: return "bad_frame_id";
    case errc::crc_mismatch: return "crc_mismatch";
    case errc::truncated: return "truncated";
    case errc::bad_variation: return "bad_variation";
    case errc::bad_variation_direction: return "bad_variation_direction";
    case errc::variation_out_of_range: return "variation_out_of_range";
    case errc::bad_can_id: return "bad_can_id";
    case errc::bad_log_line: return "bad_log_line";
    case errc::unknown_log_format: return "unknown_log_format";
    case errc::trailing_characters: return "trailing_characters";
  }
  return "unknown_error";
}

/// A sentence of explanation for an errc, for people.
[[nodiscard]] constexpr std::string_view message(errc e) noexcept {
  switch (e) {
    case errc::ok: return "no error";
    case errc::empty_input: return "empty input";
    case errc::missing_start: return "sentence does not start with '$' or '!'";
    case errc::bad_address: return "address is not 1-15 upper-case letters or digits";
    case errc::bad_character: return "byte outside printable ASCII, or '$' inside a sentence";
    case errc::missing_checksum: return "checksum required but missing";
    case errc::bad_checksum_format:
      return "checksum is not two hex digits (upper-case where required)";
    case errc::checksum_mismatch: return "checksum does not match the sentence";
    case errc::bad_line_ending: return "line does not end in CR LF";
    case errc::too_long: return "sentence longer than the maximum length";
    case errc::unknown_address: return "no known message has this address";
    case errc::wrong_address: return "sentence is not the requested message";
    case errc::too_few_fields: return "sentence ends before a required field";
    case errc::too_many_fields: return "unexpected extra fields";
    case errc::missing_field: return "required field is blank";
    case errc::bad_number: return "not a number of the field's form";
    case errc::number_too_long: return "number has too many digits";
    case errc::out_of_range: return "value outside the range the spec allows";
    case errc::bad_time: return "time is not hhmmss[.fff]";
    case errc::hour_out_of_range: return "hour out of range (00-23)";
    case errc::minute_out_of_range: return "minutes out of range (00-59)";
    case errc::second_out_of_range: return "seconds out of range (00-59)";
    case errc::bad_date: return "date is not ddmmyy";
    case errc::month_out_of_range: return "month out of range (01-12)";
    case errc::day_out_of_range: return "day out of range for its month";
    case errc::bad_latitude: return "latitude malformed or beyond 90 degrees";
    case errc::bad_longitude: return "longitude malformed or beyond 180 degrees";
    case errc::bad_hemisphere: return "hemisphere letter is not N/S or E/W";
    case errc::bad_enum: return "value is not one of the field's allowed values";
    case errc::bad_flag: return "flag is not 0 or 1";
    case errc::bad_unit: return "unit letter is not the one this field requires";
    case errc::bad_text: return "text contains a character the field may not carry";
    case errc::text_too_long: return "text longer than the field's capacity";
    case errc::bad_length: return "wrong length";
    case errc::not_finite: return "value is NaN or infinite";
    case errc::value_too_large: return "value does not fit its wire field";
    case errc::buffer_too_small: return "output buffer too small";
    case errc::bad_frame_id: return "frame identifier is not the expected one";
    case errc::crc_mismatch: return "CRC does not match the payload";
    case errc::truncated: return "input ends before the message does";
    case errc::bad_variation: return "magnetic variation is not an unsigned number of degrees";
    case errc::bad_variation_direction: return "magnetic variation letter is not E or W";
    case errc::variation_out_of_range: return "magnetic variation beyond 0..180 degrees";
    case errc::bad_can_id:
      return "not a 29-bit CAN identifier, or priority/PGN/destination it cannot carry";
    case errc::bad_log_line: return "not a CAN log line of a known format";
    case errc::unknown_log_format:
      return "the log's format header names a format seawire does not read";
    case errc::trailing_characters: return "unexpected characters after the checksum";
  }
  return "unknown error";
}

/// A value together with how getting it went. `field` is the field number as the spec counts
/// it (1 = first field after the address; 0 = the sentence as a whole), `column` the byte offset
/// into the input where the problem starts.
template <class T>
struct result {
  T value{};
  errc ec = errc::ok;
  std::uint16_t field = 0;
  std::uint16_t column = 0;

  [[nodiscard]] constexpr explicit operator bool() const noexcept { return ec == errc::ok; }
  [[nodiscard]] constexpr bool ok() const noexcept { return ec == errc::ok; }
};

namespace detail {
/// One step of building a message from values: `v`'s value into `out`, or its errc and the
/// wire `field` it was for into `r` (false then, and the caller stops there).
template <class V, class Out, class T>
[[nodiscard]] constexpr bool take(const result<V>& v, std::uint16_t field, Out& out,
                                  result<T>& r) noexcept {
  if (!v) {
    r.ec = v.ec;
    r.field = field;
    return false;
  }
  out = v.value;
  return true;
}
}  // namespace detail

}  // namespace seawire
