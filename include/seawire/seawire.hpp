// SPDX-License-Identifier: BSL-1.0
#pragma once
// seawire: codecs for the wire protocols spoken between marine vehicles and their payloads.
// Including this header gives you all of it; each part below can also be included on its own.
//
// Contract, for every part: header-only C++20; no exceptions, no RTTI, no heap, no I/O, no
// clock (time is passed in). Decoders take bytes and return result<T>: the value, or an errc
// with the field number and byte column where the input went wrong. Encoders write strictly
// (uppercase checksum, CR LF, only printable text) and refuse what the spec forbids.
//
// Contents
//   errors              seawire/error.hpp          errc, name(), message(), result<T>
//                       seawire/version.hpp        version, SEAWIRE_VERSION_*
//   nmea wire layer     seawire/nmea/              seawire::nmea -- what every NMEA-style
//                                                  protocol shares: checksum, sentence_view and
//                                                  parse_policy, framer, writer, field codecs,
//                                                  message descriptions, dispatch by address,
//                                                  builder (messages from doubles), describe
//                                                  (errors for people), to_chars (json.hpp)
//   standard sentences  seawire/standard/          seawire::standard -- NMEA 0183 sentences
//                                                  from any talker, one header each (listed in
//                                                  registry::standard_sentences)
//   kingfisher          seawire/kingfisher/        seawire::kingfisher -- Clearpath CP* / PY*
//   sandshark           seawire/sandshark/         seawire::sandshark -- Bluefin SPI BF* / BP*,
//                                                  payload and vehicle session state machines
//   robotx              seawire/robotx/            seawire::robotx -- RobotX RX* reports and
//                                                  the heartbeat scheduler
//   anello              seawire/anello/            seawire::anello -- ANELLO INS inputs:
//                                                  PAPGPSCTRL, the 0xAB00 binary frame, mixed
//                                                  NMEA + binary streams
//   nmea2000            seawire/nmea2000/          seawire::nmea2000 -- CAN identifier, PGN
//                                                  descriptions, the ANELLO input PGNs, fast
//                                                  packets, CAN log formats, JSON, log reader
//   shared layouts      seawire/bluefin/           seawire::bluefin -- the NVG/NVR layout that
//                                                  Sandshark and Kingfisher both use
//   every message       seawire/registry.hpp       seawire::registry -- each family's sets with
//                                                  the policy of the role receiving them, every
//                                                  sentence, every PGN, the frame, as type lists
//
// Not included here: seawire/fmt.hpp (fmt::formatter for every message; needs {fmt}).

// One include per line, one block per section of the contents (clang-format sorts each block).

// errors
#include "seawire/error.hpp"
#include "seawire/version.hpp"

// nmea wire layer
#include "seawire/nmea/build.hpp"
#include "seawire/nmea/checksum.hpp"
#include "seawire/nmea/describe.hpp"
#include "seawire/nmea/dispatch.hpp"
#include "seawire/nmea/fields.hpp"
#include "seawire/nmea/framer.hpp"
#include "seawire/nmea/message.hpp"
#include "seawire/nmea/sentence.hpp"
#include "seawire/nmea/stream.hpp"
#include "seawire/nmea/variation.hpp"
#include "seawire/nmea/writer.hpp"

// standard sentences: every one, through seawire/registry.hpp below

// kingfisher
#include "seawire/kingfisher/messages.hpp"

// sandshark
#include "seawire/sandshark/messages.hpp"
#include "seawire/sandshark/session.hpp"

// robotx
#include "seawire/robotx/heartbeat.hpp"
#include "seawire/robotx/hst.hpp"
#include "seawire/robotx/messages.hpp"
#include "seawire/robotx/validator.hpp"

// anello
#include "seawire/anello/frame.hpp"
#include "seawire/anello/gpsctrl.hpp"
#include "seawire/anello/inputs.hpp"
#include "seawire/anello/stream.hpp"

// nmea2000
#include "seawire/nmea2000/can_id.hpp"
#include "seawire/nmea2000/fast_packet.hpp"
#include "seawire/nmea2000/field.hpp"
#include "seawire/nmea2000/json.hpp"
#include "seawire/nmea2000/log.hpp"
#include "seawire/nmea2000/pgns.hpp"
#include "seawire/nmea2000/reader.hpp"

// every message
#include "seawire/registry.hpp"
