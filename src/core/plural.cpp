#include "hullinspect/core/plural.hpp"

namespace hullinspect {

std::string plural_noun(long long count, std::string_view noun, std::string_view plural_form) {
  if (count == 1) return std::string(noun);
  if (!plural_form.empty()) return std::string(plural_form);
  return std::string(noun) + "s";
}

std::string plural(long long count, std::string_view noun, std::string_view plural_form) {
  return std::to_string(count) + " " + plural_noun(count, noun, plural_form);
}

}  // namespace hullinspect
