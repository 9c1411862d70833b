// SPDX-License-Identifier: BSL-1.0
#pragma once
// codec<T>: how a field value of type T is read from and written to the wire. Each value type's
// header specializes it; the message layer (message.hpp) handles blanks, optionals, units and
// ranges around it.

#include <cstddef>

#include "seawire/error.hpp"
#include "seawire/nmea/sentence.hpp"
#include "seawire/nmea/writer.hpp"

namespace seawire::nmea {

/// codec<T>: `width` wire fields; read() takes them from the reader (the first is known to be
/// present and non-blank unless `allows_blank`), check() applies the value's own domain before
/// writing, write() writes them (the message layer writes the comma before the first).
/// `max_chars` is the longest text write() produces for a value check() accepts (the commas
/// between its own wire fields included): encode() sizes its buffer from it, and encode_to
/// trusts it, writing a message whose codecs' write() take any sentence_writer into a buffer
/// that holds the longest sentence they add up to without checking the room (writer.hpp).
/// write() is only ever given values check() accepted.
template <class T>
struct codec;

template <class T>
concept has_codec = requires {
  codec<T>::width;
};

}  // namespace seawire::nmea
