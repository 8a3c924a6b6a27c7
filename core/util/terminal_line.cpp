#include "util/terminal_line.h"

#include <atomic>

namespace grass::core {

namespace {
std::atomic<bool> gProgressLineOpen{false};
}  // namespace

void markProgressLineOpen() {
    gProgressLineOpen.store(true);
}

bool endProgressLine(std::FILE* out) {
    if (!gProgressLineOpen.exchange(false))
        return false;
    std::fputc('\n', out);
    return true;
}

}  // namespace grass::core
