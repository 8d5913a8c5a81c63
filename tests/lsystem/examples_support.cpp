// Based on: ABOP §1.8 (context-sensitive bracketed L-systems, p. 32: contexts skip branches)
// for the reference rewriter; the rest is plain bookkeeping for tests.
#include "examples_support.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>

#include "ramus/export.hpp"
#include "ramus/scene.hpp"

namespace ramus::test {

std::string examplePath(const std::string& file) {
    return std::string(RAMUS_SOURCE_DIR) + "/examples/lsystems/" + file;
}

LSystem loadExample(const std::string& file) { return loadLSystem(examplePath(file)); }

std::vector<std::string> listExampleFiles() {
    std::vector<std::string> files;
    const std::filesystem::path dir = std::string(RAMUS_SOURCE_DIR) + "/examples/lsystems";
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        if (entry.path().extension() == ".lsys") files.push_back(entry.path().filename());
    }
    std::sort(files.begin(), files.end());
    return files;
}

std::map<std::string, std::uint64_t> countModules(const SymbolTable& symbols,
                                                  const ModuleString& word) {
    std::vector<std::uint64_t> perId(symbols.names.size(), 0);
    for (const Module& m : word.modules) ++perId.at(m.symbol);
    std::map<std::string, std::uint64_t> counts;
    for (std::size_t id = 0; id < perId.size(); ++id) {
        if (perId[id] > 0) counts[symbols.names[id]] = perId[id];
    }
    return counts;
}

std::array<std::uint64_t, 256> CountRecurrence::after(int n) const {
    std::array<std::uint64_t, 256> counts{};
    for (char c : axiom) ++counts[static_cast<unsigned char>(c)];
    for (int step = 0; step < n; ++step) {
        std::array<std::uint64_t, 256> next{};
        for (int a = 0; a < 256; ++a) {
            if (counts[a] == 0) continue;
            const auto rule = successors.find(static_cast<char>(a));
            if (rule == successors.end()) {
                next[a] += counts[a];
                continue;
            }
            for (char b : rule->second) next[static_cast<unsigned char>(b)] += counts[a];
        }
        counts = next;
    }
    return counts;
}

std::uint64_t CountRecurrence::total(int n) const {
    const auto counts = after(n);
    std::uint64_t sum = 0;
    for (std::uint64_t c : counts) sum += c;
    return sum;
}

double drawnLength(const BranchTree& tree) {
    double length = 0.0;
    for (std::size_t i = 1; i < tree.size(); ++i) {
        const BranchNode& node = tree.node(static_cast<NodeId>(i));
        if (node.hidden || node.parent == kNoNode) continue;
        length += (node.position - tree.node(node.parent).position).norm();
    }
    return length;
}

bool allFinite(const BranchTree& tree) {
    return std::all_of(tree.nodes().begin(), tree.nodes().end(),
                       [](const BranchNode& n) { return n.position.allFinite(); });
}

bool isWellFormed(const Mesh& mesh) {
    const auto finite = [](const auto& values) {
        return std::all_of(values.begin(), values.end(),
                           [](const auto& v) { return v.allFinite(); });
    };
    if (!finite(mesh.positions) || !finite(mesh.normals) || !finite(mesh.tangents) ||
        !finite(mesh.uvs)) {
        return false;
    }
    if (mesh.indices.size() % 3 != 0) return false;
    return std::all_of(mesh.indices.begin(), mesh.indices.end(),
                       [&](std::uint32_t i) { return i < mesh.positions.size(); });
}

void writeGlbIfRequested(const Mesh& mesh, const std::string& name) {
    const char* dir = std::getenv("RAMUS_TEST_OUTPUT");
    if (dir == nullptr || *dir == '\0') return;
    std::filesystem::create_directories(dir);
    writeGlb(makeSingleMeshScene(mesh, name), std::string(dir) + "/" + name + ".glb");
}

namespace {

// Index of the `[` matching the `]` at `close`, scanning left.
std::size_t matchingOpen(const std::string& w, std::size_t close) {
    int depth = 0;
    for (std::size_t j = close + 1; j-- > 0;) {
        if (w[j] == ']') ++depth;
        if (w[j] == '[' && --depth == 0) return j;
    }
    return 0;
}

// Index just past the `]` matching the `[` at `open`, scanning right.
std::size_t pastMatchingClose(const std::string& w, std::size_t open) {
    int depth = 0;
    for (std::size_t j = open; j < w.size(); ++j) {
        if (w[j] == '[') ++depth;
        if (w[j] == ']' && --depth == 0) return j + 1;
    }
    return w.size();
}

char leftContext(const std::string& w, std::size_t i, const std::string& ignored) {
    std::size_t j = i;
    while (j-- > 0) {
        const char c = w[j];
        if (c == ']') {
            j = matchingOpen(w, j);  // a sibling branch: skip it whole
        } else if (c != '[' && ignored.find(c) == std::string::npos) {
            return c;  // `[` is our own branch's start: the parent continues to the left
        }
    }
    return 0;
}

char rightContext(const std::string& w, std::size_t i, const std::string& ignored) {
    std::size_t j = i + 1;
    while (j < w.size()) {
        const char c = w[j];
        if (c == ']') return 0;  // our branch ends: nothing follows it on this axis
        if (c == '[') {
            j = pastMatchingClose(w, j);
            continue;
        }
        if (ignored.find(c) == std::string::npos) return c;
        ++j;
    }
    return 0;
}

}  // namespace

std::string rewriteWithContext(const std::string& word, const std::vector<ContextRule>& rules,
                               const std::string& ignored) {
    std::string out;
    for (std::size_t i = 0; i < word.size(); ++i) {
        const char c = word[i];
        const ContextRule* applied = nullptr;
        for (const ContextRule& rule : rules) {
            if (rule.strict != c) continue;
            if (rule.left != 0 && leftContext(word, i, ignored) != rule.left) continue;
            if (rule.right != 0 && rightContext(word, i, ignored) != rule.right) continue;
            applied = &rule;
            break;
        }
        if (applied != nullptr) {
            out += applied->successor;
        } else {
            out += c;
        }
    }
    return out;
}

}  // namespace ramus::test
