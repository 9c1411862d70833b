// SPDX-License-Identifier: BSL-1.0
#pragma once
// seawire: codecs for the wire protocols spoken between marine vehicles and their payloads. This
// header includes all of it but seawire/fmt.hpp (which needs {fmt}); each part may be included on
// its own. The parts: docs/api.md. Contract, for every part: no exceptions, RTTI, heap, I/O or
// clock; decoders return result<T> (the value, or an errc with the field and column); encoders
// write strictly and refuse what the spec forbids.

// One include per line, one block per section of the contents (clang-format sorts each block).

// errors
#include "seawire/error.hpp"
#include "seawire/version.hpp"

// nmea wire layer
#include "seawire/nmea/build.hpp"
#include "seawire/nmea/checksum.hpp"
#include "seawire/nmea/describe.hpp"  // the former name of error_text.hpp
#include "seawire/nmea/dispatch.hpp"
#include "seawire/nmea/error_text.hpp"
#include "seawire/nmea/fields.hpp"
#include "seawire/nmea/framer.hpp"
#include "seawire/nmea/heading.hpp"
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
#include "seawire/nmea2000/canboat.hpp"
#include "seawire/nmea2000/fast_packet.hpp"
#include "seawire/nmea2000/field.hpp"
#include "seawire/nmea2000/json.hpp"
#include "seawire/nmea2000/log.hpp"
#include "seawire/nmea2000/pgns.hpp"
#include "seawire/nmea2000/reader.hpp"

// every message
#include "seawire/registry.hpp"
