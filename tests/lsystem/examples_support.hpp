// Helpers for the tests of the shipped example L-systems (examples/lsystems/*.lsys): loading,
// counting modules, independent count recurrences and a reference context-sensitive rewriter.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "ramus/branch_tree.hpp"
#include "ramus/lsystem.hpp"
#include "ramus/mesh.hpp"

namespace ramus::test {

/// Absolute path of examples/lsystems/<file>.
std::string examplePath(const std::string& file);

/// Parses examples/lsystems/<file>.
LSystem loadExample(const std::string& file);

/// File names (e.g. "abop_1_24a.lsys") of every .lsys in examples/lsystems, sorted.
std::vector<std::string> listExampleFiles();

/// How often each module name occurs in `word`.
std::map<std::string, std::uint64_t> countModules(const SymbolTable& symbols,
                                                  const ModuleString& word);

/// Symbol counts of a D0L system over single-character symbols, by the production matrix:
/// counts_{k+1}[b] = Σ_a counts_k[a] · (occurrences of b in the successor of a); symbols without
/// a successor map to themselves. Parameters play no part in how many modules a step makes
/// when every production is unconditional, so parametric systems are written here without
/// them ("A -> F[&B]/A" for "A(l) -> F(l)[&(a)B(l*r)]/(d)A(l*r1)").
struct CountRecurrence {
    std::string axiom;
    std::map<char, std::string> successors;

    /// Count of every byte value after n steps.
    std::array<std::uint64_t, 256> after(int n) const;
    /// Total module count after n steps.
    std::uint64_t total(int n) const;
};

/// Sum of the lengths of all drawn (not hidden) edges.
double drawnLength(const BranchTree& tree);

/// True when every node position is finite.
bool allFinite(const BranchTree& tree);

/// True when positions, normals, tangents and uvs are finite and every index is in range.
bool isWellFormed(const Mesh& mesh);

/// Writes `mesh` as <$RAMUS_TEST_OUTPUT>/<name>.glb when the variable is set; no-op otherwise.
void writeGlbIfRequested(const Mesh& mesh, const std::string& name);

/// ABOP §1.8 context-sensitive bracketed rewriting of a word of single-character symbols, for
/// rules "left < strict > right -> successor" with single-symbol contexts. The left context
/// skips ignored symbols and whole bracketed branches and steps out of the module's own branch
/// (over its `[`); the right context skips ignored symbols and whole branches but ends at the
/// `]` that closes the module's branch. Context-free rules have left = right = 0.
struct ContextRule {
    char left = 0;
    char strict = 0;
    char right = 0;
    std::string successor;
};
std::string rewriteWithContext(const std::string& word, const std::vector<ContextRule>& rules,
                               const std::string& ignored);

}  // namespace ramus::test
