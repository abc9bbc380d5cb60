#include "core/glslang_words.h"

#include <algorithm>
#include <cctype>
#include <utility>

namespace rm {

namespace {

// The grammar's names (glslang.y) that are not their word in upper case.
constexpr std::pair<std::string_view, std::string_view> kTokens[] = {
    {"LEFT_PAREN", "'('"},      {"RIGHT_PAREN", "')'"},     {"LEFT_BRACKET", "'['"},    {"RIGHT_BRACKET", "']'"},
    {"LEFT_BRACE", "'{'"},      {"RIGHT_BRACE", "'}'"},     {"DOT", "'.'"},             {"COMMA", "','"},
    {"COLON", "':'"},           {"EQUAL", "'='"},           {"SEMICOLON", "';'"},       {"BANG", "'!'"},
    {"DASH", "'-'"},            {"TILDE", "'~'"},           {"PLUS", "'+'"},            {"STAR", "'*'"},
    {"SLASH", "'/'"},           {"PERCENT", "'%'"},         {"LEFT_ANGLE", "'<'"},      {"RIGHT_ANGLE", "'>'"},
    {"VERTICAL_BAR", "'|'"},    {"CARET", "'^'"},           {"AMPERSAND", "'&'"},       {"QUESTION", "'?'"},
    {"LEFT_OP", "'<<'"},        {"RIGHT_OP", "'>>'"},       {"INC_OP", "'++'"},         {"DEC_OP", "'--'"},
    {"LE_OP", "'<='"},          {"GE_OP", "'>='"},          {"EQ_OP", "'=='"},          {"NE_OP", "'!='"},
    {"AND_OP", "'&&'"},         {"OR_OP", "'||'"},          {"XOR_OP", "'^^'"},         {"MUL_ASSIGN", "'*='"},
    {"DIV_ASSIGN", "'/='"},     {"ADD_ASSIGN", "'+='"},     {"MOD_ASSIGN", "'%='"},     {"LEFT_ASSIGN", "'<<='"},
    {"RIGHT_ASSIGN", "'>>='"},  {"AND_ASSIGN", "'&='"},     {"XOR_ASSIGN", "'^='"},     {"OR_ASSIGN", "'|='"},
    {"SUB_ASSIGN", "'-='"},     {"IDENTIFIER", "identifier"},   {"TYPE_NAME", "type name"},
    {"FLOATCONSTANT", "float constant"},                  {"DOUBLECONSTANT", "double constant"},
    {"INTCONSTANT", "int constant"},                     {"UINTCONSTANT", "uint constant"},
    {"BOOLCONSTANT", "bool constant"},                    {"STRING_LITERAL", "string"},
    {"HIGH_PRECISION", "'highp'"}, {"MEDIUM_PRECISION", "'mediump'"}, {"LOW_PRECISION", "'lowp'"},
    {"SAMPLER2D", "'sampler2D'"}, {"SAMPLER3D", "'sampler3D'"}, {"SAMPLERCUBE", "'samplerCube'"},
    {"SAMPLER2DSHADOW", "'sampler2DShadow'"}, {"SAMPLER2DARRAY", "'sampler2DArray'"},
    {"ISAMPLER2D", "'isampler2D'"}, {"USAMPLER2D", "'usampler2D'"},
    {"TERMINATE_INVOCATION", "'terminateInvocationEXT'"}, {"$end", "the end of the text"},
    {"YYEOF", "the end of the text"}, {"end of file", "the end of the text"},
};

// Keywords whose grammar name is the word in upper case ('return', 'vec4',
// 'mat2x3'): letters, digits and no '_' (SAMPLER1DARRAY and its like keep
// their grammar name, as too rare to spell here).
std::string spelt(std::string_view token) {
  for (const auto& [name, words] : kTokens)
    if (token == name) return std::string(words);
  const bool keyword = !token.empty() && std::isupper(static_cast<unsigned char>(token[0])) &&
                       std::all_of(token.begin(), token.end(), [](char c) {
                         return std::isupper(static_cast<unsigned char>(c)) || std::isdigit(static_cast<unsigned char>(c));
                       });
  if (!keyword || token.find("SAMPLER") != std::string_view::npos || token.find("IMAGE") != std::string_view::npos ||
      token.find("TEXTURE") != std::string_view::npos)
    return std::string(token);
  std::string word = "'";
  for (char c : token) word += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return word + "'";
}

// Bison's "syntax error, unexpected A, expecting B or C or D": each token
// after "unexpected " and "expecting " or " or " is spelt.
std::string spell_syntax_error(std::string_view message) {
  std::string out;
  size_t at = 0;
  auto copy_to = [&](size_t end) {
    out += message.substr(at, end - at);
    at = end;
  };
  for (const std::string_view lead : {"unexpected ", "expecting "}) {
    const size_t found = message.find(lead, at);
    if (found == std::string_view::npos) continue;
    copy_to(found + lead.size());
    while (true) {
      const size_t end = std::min(message.find(", ", at), message.find(" or ", at));
      const size_t stop = end == std::string_view::npos ? message.size() : end;
      out += spelt(message.substr(at, stop - at));
      at = stop;
      if (at >= message.size() || message.compare(at, 4, " or ") != 0) break;
      copy_to(at + 4);
    }
  }
  copy_to(message.size());
  return out;
}

}  // namespace

std::string plain_words(std::string_view message) {
  constexpr std::string_view kExhausted = "memory exhausted";
  if (message.size() >= kExhausted.size() && message.substr(message.size() - kExhausted.size()) == kExhausted)
    return "nested too deeply for glslang's parser (its stack holds 10000 levels of parentheses, "
           "brackets and blocks)";
  constexpr std::string_view kNoToken = "'' :";
  if (message.substr(0, kNoToken.size()) == kNoToken) {
    message.remove_prefix(kNoToken.size());
    message.remove_prefix(std::min(message.find_first_not_of(' '), message.size()));
  }
  if (message.substr(0, 12) == "syntax error") return spell_syntax_error(message);
  return std::string(message);
}

}  // namespace rm
