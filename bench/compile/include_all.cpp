// SPDX-License-Identifier: BSL-1.0
// Including everything, using nothing.
#include <seawire/seawire.hpp>

int main() { return 0; }
