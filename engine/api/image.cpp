// Output names.
#include "rmsc/image.hpp"
#include "rmsc/error.hpp"

#include <string>

namespace rmsc::api {

Aov parseAov(std::string_view name) {
    if (name == "color") return Aov::Color;
    if (name == "depth") return Aov::Depth;
    if (name == "normal") return Aov::Normal;
    if (name == "id") return Aov::Id;
    if (name == "steps") return Aov::Steps;
    throw Error(ErrorKind::Usage,
                "aov: expected color, depth, normal, id or steps, got '" + std::string(name) + "'");
}

} // namespace rmsc::api
