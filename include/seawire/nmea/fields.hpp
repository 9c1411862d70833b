// SPDX-License-Identifier: BSL-1.0
#pragma once
// Field values as the wire has them, one header per kind: each keeps enough of the text to write
// it back exactly ("4.50", an unpadded longitude) and refuses values outside its domain; its
// codec reads and writes `width` wire fields (blanks, optionals, units, ranges: message.hpp).

#include "seawire/nmea/codec.hpp"     // codec<T>, has_codec
#include "seawire/nmea/decimal.hpp"   // decimal, integers, 0/1 flags
#include "seawire/nmea/enum.hpp"      // letter and word enums
#include "seawire/nmea/integer.hpp"   // integer<T>: whole numbers
#include "seawire/nmea/position.hpp"  // latitude, longitude, decimal_latitude, decimal_longitude
#include "seawire/nmea/text.hpp"      // text<N>, talker_id
#include "seawire/nmea/time.hpp"      // time_of_day, date
