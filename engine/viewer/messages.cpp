// Problems and notices (see messages.hpp).
#include "messages.hpp"

#include <cstdio>

namespace rmsc::app {

void Messages::notice(const std::string& text) {
    std::fprintf(stderr, "rmsc view: %s\n", text.c_str());
    notices.push_back({text, std::chrono::steady_clock::now()});
    while (notices.size() > 6)
        notices.pop_front();
}

} // namespace rmsc::app
