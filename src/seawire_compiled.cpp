// SPDX-License-Identifier: BSL-1.0
// The translation unit of seawire::compiled: the one definition of what the headers only declare
// when SEAWIRE_SEPARATE_COMPILATION is defined.
#include <seawire/impl/src.hpp>
