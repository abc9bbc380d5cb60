#include "core/glslang_words.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <regex>
#include <utility>

namespace rm {

namespace {

// Tokens of glslang's grammar (glslang.y) that are not their name in lower case.
constexpr std::pair<std::string_view, std::string_view> kSpellings[] = {
    {"LEFT_PAREN", "("},     {"RIGHT_PAREN", ")"},     {"LEFT_BRACKET", "["},   {"RIGHT_BRACKET", "]"},
    {"LEFT_BRACE", "{"},     {"RIGHT_BRACE", "}"},     {"DOT", "."},            {"COMMA", ","},
    {"COLON", ":"},          {"EQUAL", "="},           {"SEMICOLON", ";"},      {"BANG", "!"},
    {"DASH", "-"},           {"TILDE", "~"},           {"PLUS", "+"},           {"STAR", "*"},
    {"SLASH", "/"},          {"PERCENT", "%"},         {"LEFT_ANGLE", "<"},     {"RIGHT_ANGLE", ">"},
    {"VERTICAL_BAR", "|"},   {"CARET", "^"},           {"AMPERSAND", "&"},      {"QUESTION", "?"},
    {"LEFT_OP", "<<"},       {"RIGHT_OP", ">>"},       {"INC_OP", "++"},        {"DEC_OP", "--"},
    {"LE_OP", "<="},         {"GE_OP", ">="},          {"EQ_OP", "=="},         {"NE_OP", "!="},
    {"AND_OP", "&&"},        {"OR_OP", "||"},          {"XOR_OP", "^^"},        {"MUL_ASSIGN", "*="},
    {"DIV_ASSIGN", "/="},    {"ADD_ASSIGN", "+="},     {"MOD_ASSIGN", "%="},    {"LEFT_ASSIGN", "<<="},
    {"RIGHT_ASSIGN", ">>="}, {"AND_ASSIGN", "&="},     {"XOR_ASSIGN", "^="},    {"OR_ASSIGN", "|="},
    {"SUB_ASSIGN", "-="},    {"HIGH_PRECISION", "highp"}, {"MEDIUM_PRECISION", "mediump"},
    {"LOW_PRECISION", "lowp"}, {"SAMPLER2D", "sampler2D"}, {"SAMPLER3D", "sampler3D"},
    {"SAMPLERCUBE", "samplerCube"}, {"SAMPLER2DSHADOW", "sampler2DShadow"}, {"SAMPLER2DARRAY", "sampler2DArray"},
    {"ISAMPLER2D", "isampler2D"}, {"USAMPLER2D", "usampler2D"},
};

// Tokens that stand for a class of words.
constexpr std::pair<std::string_view, std::string_view> kClasses[] = {
    {"IDENTIFIER", "identifier"},          {"TYPE_NAME", "type name"},         {"FLOATCONSTANT", "float constant"},
    {"DOUBLECONSTANT", "double constant"}, {"INTCONSTANT", "int constant"},    {"UINTCONSTANT", "uint constant"},
    {"BOOLCONSTANT", "bool constant"},     {"STRING_LITERAL", "string"},
};

// A grammar name spelt as the code does, quoted; a class named; any other
// name (SAMPLER1DARRAY) as glslang gives it.
std::string spelt(std::string_view token) {
  if (const auto spelling = token_spelling(token)) return "'" + *spelling + "'";
  for (const auto& [name, words] : kClasses)
    if (token == name) return std::string(words);
  return std::string(token);
}

// Bison's "syntax error, unexpected A, expecting B or C or D": each token
// after "unexpected " and "expecting " or " or " is spelt, and after the
// host's "before " (core/left_open.h: "expecting B before A").
std::string spell_syntax_error(std::string_view message) {
  std::string out;
  size_t at = 0;
  auto copy_to = [&](size_t end) {
    out += message.substr(at, end - at);
    at = end;
  };
  for (const std::string_view lead : {"unexpected ", "expecting ", "before "}) {
    const size_t found = message.find(lead, at);
    if (found == std::string_view::npos) continue;
    copy_to(found + lead.size());
    while (true) {
      const size_t end = std::min({message.find(", ", at), message.find(" or ", at), message.find(" before ", at)});
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

// glslang's description of a type, the part between its quotes (" temp
// 3-component vector of float"), as GLSL writes the type ("vec3"). The
// qualifiers glslang adds of its own (temp, global) go; the code's stay.
std::string glsl_type(std::string description) {
  using Rule = std::pair<std::regex, const char*>;
  static const std::array<Rule, 10> kRules = {{
      {std::regex(R"(\b(temp|global) )"), ""},
      {std::regex(R"((\d)-component vector of float\b)"), "vec$1"},
      {std::regex(R"((\d)-component vector of double\b)"), "dvec$1"},
      {std::regex(R"((\d)-component vector of int\b)"), "ivec$1"},
      {std::regex(R"((\d)-component vector of uint\b)"), "uvec$1"},
      {std::regex(R"((\d)-component vector of bool\b)"), "bvec$1"},
      {std::regex(R"((\d)X\1 matrix of float\b)"), "mat$1"},
      {std::regex(R"((\d)X(\d) matrix of float\b)"), "mat$1x$2"},
      {std::regex(R"((\d)X(\d) matrix of double\b)"), "dmat$1x$2"},
      {std::regex(R"((\d+)-element array of (\w+))"), "$2[$1]"},
  }};
  for (const auto& [pattern, glsl] : kRules) description = std::regex_replace(description, pattern, glsl);
  return description;
}

// Every quoted type in `message` (glslang quotes a token as "'='", and a
// type with a blank first: "' const float'") as GLSL writes it. glslang
// cuts a message at about 1 KB, so a struct's type may run to the end
// with no closing quote.
std::string with_glsl_types(std::string_view message) {
  std::string out;
  size_t at = 0;
  for (size_t open = message.find('\''); open != std::string_view::npos && at < message.size();
       open = message.find('\'', at + 1)) {
    const size_t close = std::min(message.find('\'', open + 1), message.size());
    out += message.substr(at, open + 1 - at);
    const std::string_view quoted = message.substr(open + 1, close - open - 1);
    out += quoted.substr(0, 1) == " " ? glsl_type(std::string(quoted.substr(1))) : std::string(quoted);
    at = close;
  }
  out += message.substr(at);
  return out;
}

}  // namespace

std::optional<std::string> token_spelling(std::string_view name) {
  for (const auto& [token, spelling] : kSpellings)
    if (name == token) return std::string(spelling);
  for (const auto& [token, words] : kClasses)
    if (name == token) return std::nullopt;
  // A keyword whose name is its word in upper case (RETURN, VEC4, MAT2X3);
  // the samplers, images and textures the table lacks have letters in
  // lower and upper case.
  const bool keyword = !name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
    return std::isupper(static_cast<unsigned char>(c)) || std::isdigit(static_cast<unsigned char>(c));
  }) && std::isupper(static_cast<unsigned char>(name[0]));
  if (!keyword || name.find("SAMPLER") != std::string_view::npos || name.find("IMAGE") != std::string_view::npos ||
      name.find("TEXTURE") != std::string_view::npos)
    return std::nullopt;
  std::string word;
  for (char c : name) word += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return word;
}

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
  std::string plain = with_glsl_types(message);
  // glslang's name for '=', and the second blank it puts after its token's ':'.
  if (plain.rfind("'assign' :", 0) == 0) plain.replace(0, 8, "'='");
  if (const size_t colon = plain.find("' :  "); colon != std::string::npos && plain[0] == '\'') plain.erase(colon + 3, 1);
  return plain;
}

}  // namespace rm
