// Internal: the .lsys parser (docs/lsystem.md). One object parses one text; its member functions
// are split over parser.cpp (file structure, headers, constants), word_parser.cpp (module
// words) and production_parser.cpp (productions).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

#include "lsystem/compiled_rules.hpp"
#include "lsystem/expression.hpp"
#include "lsystem/text_line.hpp"
#include "ramus/lsystem.hpp"

namespace ramus::detail {

/// What a module word is parsed as.
enum class WordMode {
    Axiom,      ///< parameters are constant expressions, evaluated while parsing
    Successor,  ///< parameters are expressions of formal parameters and constants
    Pattern,    ///< parameters are formal parameter names (predecessor and contexts)
    Plain,      ///< no parameters allowed (ignore: and consider: lists)
};

/// One module of a parsed word, before it is turned into runtime data.
struct WordModule {
    std::uint32_t symbol = 0;
    std::size_t offset = 0;            ///< byte offset of the name in its line
    std::vector<CompiledExpr> params;  ///< Axiom and Successor modes
    std::vector<std::pair<std::string, std::size_t>> formals;  ///< Pattern mode: name, offset
};

class LSystemParser {
public:
    LSystemParser(std::string_view text, const std::string& fileName, const ParseOptions& options);
    LSystem run();

private:
    // parser.cpp — file structure
    void splitLines(std::string_view text);
    void declarationPass();
    void mainPass();
    void parseDefine(const TextLine& line, std::size_t pos);
    void parseModuleDeclaration(const TextLine& line, std::size_t pos);
    void parseSymbolList(const TextLine& line, std::size_t pos, bool consider);
    void parseHeader(const TextLine& line, std::size_t colon);
    void parseNumericHeader(const TextLine& line, const std::string& key, std::size_t valuePos);
    void parseAxiom(const TextLine& line, std::size_t pos);
    void parseTropism(const TextLine& line, std::size_t pos);
    double constantValue(const TextLine& line, std::size_t begin, std::size_t end,
                         const char* what);
    void finish();
    void checkOverrides();
    void buildSymbolRules();

    // word_parser.cpp — module words
    std::uint32_t internSymbol(std::string_view name);
    std::size_t moduleNameLength(std::string_view text, std::size_t pos) const;
    std::vector<WordModule> parseWord(const TextLine& line, std::size_t begin, std::size_t end,
                                      WordMode mode, const ExprScope* scope);
    void parseParams(const TextLine& line, std::size_t& pos, WordMode mode, const ExprScope* scope,
                     WordModule& module);
    void checkBrackets(const TextLine& line, const std::vector<WordModule>& word,
                       const char* what) const;
    bool isIgnored(std::uint32_t symbol) const;

    // production_parser.cpp — productions
    void parseProduction(const TextLine& line, std::size_t arrow, std::size_t arrowLength);
    void parsePredecessor(const TextLine& line, std::size_t end, Rule& rule,
                          std::vector<std::string>& formals);
    std::pair<std::size_t, std::size_t> findContextMarkers(const TextLine& line,
                                                           std::size_t end) const;
    void parseLeftContext(const TextLine& line, std::size_t lt, Rule& rule,
                          std::vector<std::string>& formals, std::vector<std::size_t>& offsets);
    void parseRightContext(const TextLine& line, std::size_t gt, std::size_t end, Rule& rule,
                           std::vector<std::string>& formals, std::vector<std::size_t>& offsets);
    void addPattern(const TextLine& line, const std::vector<WordModule>& word,
                    std::vector<std::string>& formals, std::vector<std::size_t>& formalOffsets,
                    bool isContext);
    std::int32_t addExpr(const TextLine& line, const CompiledExpr& expr);
    void buildSuccessor(const TextLine& line, const std::vector<WordModule>& word, Rule& rule);
    std::int32_t compileClause(const TextLine& line, std::size_t begin, std::size_t end,
                               const ExprScope& scope, const char* expectedAfter);

    std::string fileName_;
    const ParseOptions& options_;
    std::vector<TextLine> lines_;
    std::vector<std::uint8_t> isDeclaration_;  ///< per line: handled by declarationPass
    LSystem system_;
    std::shared_ptr<CompiledRules> rules_;
    ConstantTable constants_;
    std::unordered_map<std::string, std::uint32_t> symbolIds_;
    std::vector<std::string> multiNames_;  ///< declared multi-character module names
    std::vector<std::uint8_t> listed_;     ///< symbols named by ignore: / consider:
    bool considerMode_ = false;
    int listLine_ = 0;             ///< line of the first ignore:/consider:, 0 if none
    std::vector<Rule> fileRules_;  ///< productions in file order
    std::unordered_map<std::string, int> headerLines_;  ///< header key -> first line
    bool haveAxiom_ = false;
};

}  // namespace ramus::detail
