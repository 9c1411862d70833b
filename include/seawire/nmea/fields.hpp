// SPDX-License-Identifier: BSL-1.0
#pragma once
// Field values as the wire has them, and the codec that reads and writes each one: one header
// per kind of value.
//
// Every value type keeps enough of the text to write it back exactly ("4.50" stays "4.50", an
// unpadded longitude stays unpadded) and rejects values outside its domain. A codec reads
// `width` wire fields from a field_reader and writes them to a writer; the message layer
// (message.hpp) handles blanks, optionals, units and ranges around it.

#include "seawire/nmea/codec.hpp"     // codec<T>, has_codec
#include "seawire/nmea/decimal.hpp"   // decimal, integers, 0/1 flags
#include "seawire/nmea/enum.hpp"      // letter and word enums
#include "seawire/nmea/integer.hpp"   // integer<T>: whole numbers
#include "seawire/nmea/position.hpp"  // latitude, longitude, decimal_latitude, decimal_longitude
#include "seawire/nmea/text.hpp"      // text<N>, talker_id
#include "seawire/nmea/time.hpp"      // time_of_day, date
