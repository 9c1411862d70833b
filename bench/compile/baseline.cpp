// SPDX-License-Identifier: BSL-1.0
// The floor: the standard headers every seawire translation unit pulls in anyway.
#include <chrono>
#include <optional>
#include <string_view>
#include <variant>

int main() { return 0; }
