// SPDX-License-Identifier: BSL-1.0
// A letter field's letters are its enum's enumerators: an enum with none that is a digit or an
// ASCII letter cannot be a field (nothing could be received in it), nor one with an enumerator
// that is a space or punctuation (that one could never be sent or read). Each ctest case compiles
// this file with one CASE defined and expects the compiler's message; CASE ok must compile.
#include "seawire/nmea/enum.hpp"

namespace n = seawire::nmea;

#if defined(CASE_ok)
enum class mode : char { automatic = 'A', manual = 'M' };
static_assert(n::enum_letters<mode> == "AM");
#elif defined(CASE_no_letters)
enum class mode : char { plus = '+', minus = '-' };
static_assert(n::enum_letters<mode>.empty());
#elif defined(CASE_punctuation)
enum class trend : char { rising = 'R', falling = 'F', steady = '=' };
static_assert(n::enum_letters<trend> == "FR");
#elif defined(CASE_in_class_template)
template <class T>
struct holder {
  enum class mode : char { automatic = 'A', manual = 'M' };
};
static_assert(n::enum_letters<holder<int>::mode> == "AM");
#endif

int main() { return 0; }
