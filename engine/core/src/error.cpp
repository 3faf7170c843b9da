#include "throng/core/error.h"

namespace throng {

std::string Error::describe() const {
    std::string out;
    if (!location.file.empty()) {
        out += location.file;
        if (location.line > 0) {
            out += ':' + std::to_string(location.line);
            if (location.column > 0) out += ':' + std::to_string(location.column);
        }
        out += ": ";
    }
    out += "error: ";
    out += message;
    return out;
}

}  // namespace throng
