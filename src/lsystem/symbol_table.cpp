#include "ramus/lsystem.hpp"

namespace ramus {

int SymbolTable::find(std::string_view name) const {
    for (std::size_t i = 0; i < names.size(); ++i) {
        if (names[i] == name) return static_cast<int>(i);
    }
    return -1;
}

}  // namespace ramus
