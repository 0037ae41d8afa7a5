#pragma once

namespace hullinspect {
inline constexpr const char* kVersion = HULLINSPECT_VERSION;
}
