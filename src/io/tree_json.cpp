#include "ramus/tree_json.hpp"

#include <cstdio>

#include "ramus/error.hpp"

namespace ramus {

namespace {
void appendNumber(std::string& out, double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.17g", value);
    out += buffer;
}
}  // namespace

std::string encodeTreeJson(const BranchTree& tree, std::span<const double> radii) {
    RAMUS_ASSERT(radii.size() == tree.size());
    std::string out = "{\"nodes\":[";
    out.reserve(tree.size() * 96);
    for (std::size_t i = 0; i < tree.size(); ++i) {
        const BranchNode& n = tree.nodes()[i];
        if (i > 0) out += ",\n";
        out += "{\"id\":" + std::to_string(i) + ",\"parent\":" + std::to_string(n.parent);
        out += ",\"position\":[";
        appendNumber(out, n.position.x());
        out += ',';
        appendNumber(out, n.position.y());
        out += ',';
        appendNumber(out, n.position.z());
        out += "],\"radius\":";
        appendNumber(out, radii[i]);
        out += ",\"branch_depth\":" + std::to_string(n.branchDepth);
        if (n.hidden) out += ",\"hidden\":true";
        out += '}';
    }
    out += "]}\n";
    return out;
}

}  // namespace ramus
