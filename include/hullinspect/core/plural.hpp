#pragma once
// Counted nouns for messages: "1 UAV", "4 UAVs", "1 directory", "2 directories".

#include <string>
#include <string_view>

namespace hullinspect {

/// "<count> <noun>" with the noun's plural form unless count is exactly 1. The plural defaults to
/// noun + "s"; pass it for irregular nouns (plural(n, "directory", "directories")).
std::string plural(long long count, std::string_view noun, std::string_view plural_noun = {});

/// The noun alone in the form that fits count ("cell" or "cells").
std::string plural_noun(long long count, std::string_view noun, std::string_view plural_noun = {});

}  // namespace hullinspect
