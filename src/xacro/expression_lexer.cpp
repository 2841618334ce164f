// Python's tokenizer for expressions: number literals (with underscores, 0x/0o/0b prefixes,
// exponents, imaginary `j`), string literals (quotes, escapes, raw and triple-quoted forms), names, operators.
#include "xacro/internal/expression_lexer.h"

#include <cctype>
#include <cstdlib>
#include <cstring>

namespace urdfsnap::xacro {
namespace {

[[noreturn]] void SyntaxError(const std::string& what = "invalid syntax") {
  throw EvalError(what + " (<expression>, line 1)");
}

bool IsNameStart(unsigned char c) { return std::isalpha(c) || c == '_' || c >= 0x80; }
bool IsNameChar(unsigned char c) { return std::isalnum(c) || c == '_' || c >= 0x80; }

void AppendUtf8(std::string& out, unsigned long cp) {
  if (cp < 0x80) {
    out += static_cast<char>(cp);
  } else if (cp < 0x800) {
    out += static_cast<char>(0xc0 | (cp >> 6));
    out += static_cast<char>(0x80 | (cp & 0x3f));
  } else if (cp < 0x10000) {
    out += static_cast<char>(0xe0 | (cp >> 12));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3f));
    out += static_cast<char>(0x80 | (cp & 0x3f));
  } else {
    out += static_cast<char>(0xf0 | (cp >> 18));
    out += static_cast<char>(0x80 | ((cp >> 12) & 0x3f));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3f));
    out += static_cast<char>(0x80 | (cp & 0x3f));
  }
}

// digits of `base` with single underscores between them, starting at `k`; returns them without
// the underscores
std::string ReadDigits(const std::string& s, size_t& k, int base) {
  std::string digits;
  auto ok = [&](char c) {
    if (base == 16) return std::isxdigit(static_cast<unsigned char>(c)) != 0;
    return c >= '0' && c < static_cast<char>('0' + base);
  };
  while (k < s.size()) {
    if (ok(s[k])) {
      digits += s[k++];
    } else if (s[k] == '_' && !digits.empty() && k + 1 < s.size() && ok(s[k + 1])) {
      ++k;
    } else {
      break;
    }
  }
  return digits;
}

Value IntFromDigits(const std::string& digits, int base) {
  Int value = 0;
  for (char c : digits) {
    const int d = std::isdigit(static_cast<unsigned char>(c)) ? c - '0' : std::tolower(c) - 'a' + 10;
    if (__builtin_mul_overflow(value, base, &value) || __builtin_add_overflow(value, d, &value)) {
      throw EvalError("integer literal too large");
    }
  }
  return Value::Integer(value);
}

Token ReadNumber(const std::string& s, size_t& k) {
  Token t;
  t.kind = Token::Kind::kNumber;
  if (s[k] == '0' && k + 1 < s.size() && std::strchr("xXoObB", s[k + 1])) {
    const char p = static_cast<char>(std::tolower(s[k + 1]));
    const int base = p == 'x' ? 16 : (p == 'o' ? 8 : 2);
    k += 2;
    if (k < s.size() && s[k] == '_') ++k;
    const std::string digits = ReadDigits(s, k, base);
    if (digits.empty()) SyntaxError();
    t.number = IntFromDigits(digits, base);
  } else {
    std::string text = ReadDigits(s, k, 10);
    bool is_float = false;
    if (k < s.size() && s[k] == '.') {
      is_float = true;
      ++k;
      text += "." + ReadDigits(s, k, 10);
    }
    if (k < s.size() && (s[k] == 'e' || s[k] == 'E')) {
      size_t j = k + 1;
      std::string exp = "e";
      if (j < s.size() && (s[j] == '+' || s[j] == '-')) exp += s[j++];
      const std::string digits = ReadDigits(s, j, 10);
      if (!digits.empty()) {
        is_float = true;
        k = j;
        text += exp + digits;
      }
    }
    if (k < s.size() && (s[k] == 'j' || s[k] == 'J')) {
      // an imaginary literal: 2j, 1.5e3J
      ++k;
      t.number = Value::Complex(0.0, std::strtod(text.c_str(), nullptr));
    } else if (is_float) {
      t.number = Value::Float(std::strtod(text.c_str(), nullptr));
    } else {
      // Python forbids leading zeros in decimal integer literals ("007")
      if (text.size() > 1 && text[0] == '0' && text.find_first_not_of('0') != std::string::npos) {
        SyntaxError("leading zeros in decimal integer literals are not permitted");
      }
      t.number = IntFromDigits(text, 10);
    }
  }
  if (k < s.size() && IsNameChar(static_cast<unsigned char>(s[k]))) SyntaxError();
  return t;
}

Token ReadString(const std::string& s, size_t& k, bool raw) {
  const char q = s[k];
  const bool triple = s.compare(k, 3, std::string(3, q)) == 0;
  k += triple ? 3 : 1;
  Token t;
  t.kind = Token::Kind::kString;
  while (true) {
    if (k >= s.size()) SyntaxError("unterminated string literal");
    const char c = s[k];
    if (triple ? s.compare(k, 3, std::string(3, q)) == 0 : c == q) {
      k += triple ? 3 : 1;
      return t;
    }
    if (c == '\n' && !triple) SyntaxError("unterminated string literal");
    if (c != '\\' || k + 1 >= s.size()) {
      t.text += c;
      ++k;
      continue;
    }
    const char e = s[k + 1];
    if (raw) {
      t.text += c;
      t.text += e;
      k += 2;
      continue;
    }
    k += 2;
    switch (e) {
      case 'n': t.text += '\n'; break;
      case 't': t.text += '\t'; break;
      case 'r': t.text += '\r'; break;
      case '0': t.text += '\0'; break;
      case 'a': t.text += '\a'; break;
      case 'b': t.text += '\b'; break;
      case 'f': t.text += '\f'; break;
      case 'v': t.text += '\v'; break;
      case '\\': t.text += '\\'; break;
      case '\'': t.text += '\''; break;
      case '"': t.text += '"'; break;
      case '\n': break;
      case 'x':
      case 'u':
      case 'U': {
        const size_t n = e == 'x' ? 2 : (e == 'u' ? 4 : 8);
        if (k + n > s.size()) SyntaxError("truncated escape");
        const std::string hex = s.substr(k, n);
        for (char h : hex) {
          if (!std::isxdigit(static_cast<unsigned char>(h))) SyntaxError("truncated escape");
        }
        AppendUtf8(t.text, std::strtoul(hex.c_str(), nullptr, 16));
        k += n;
        break;
      }
      default:
        t.text += '\\';
        t.text += e;
    }
  }
}

}  // namespace

std::vector<Token> Tokenize(const std::string& s) {
  // long operator chains nest as deeply as they are long; bounding them bounds evaluation's stack
  constexpr size_t kMaxTokens = 20000;
  static const char* const kOps[] = {"**", "//", "==", "!=", "<=", ">=", "<<", ">>", "+", "-", "*",
                                     "/", "%", "<", ">", "(", ")", "[", "]", "{", "}", ",", ":",
                                     ".", "~", "&", "|", "^", "="};
  std::vector<Token> tokens;
  size_t k = 0;
  while (k < s.size()) {
    const unsigned char c = s[k];
    if (c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f') {
      ++k;
      continue;
    }
    if (std::isdigit(c) || (c == '.' && k + 1 < s.size() && std::isdigit(static_cast<unsigned char>(s[k + 1])))) {
      tokens.push_back(ReadNumber(s, k));
      continue;
    }
    if (c == '\'' || c == '"') {
      tokens.push_back(ReadString(s, k, false));
      continue;
    }
    if (IsNameStart(c)) {
      size_t j = k;
      while (j < s.size() && IsNameChar(static_cast<unsigned char>(s[j]))) ++j;
      const std::string name = s.substr(k, j - k);
      if (j < s.size() && (s[j] == '\'' || s[j] == '"') && (name == "r" || name == "R" || name == "u" || name == "U")) {
        k = j;
        tokens.push_back(ReadString(s, k, name == "r" || name == "R"));
        continue;
      }
      tokens.push_back(Token{Token::Kind::kName, name, {}});
      k = j;
      continue;
    }
    if (tokens.size() > kMaxTokens) throw EvalError("expression too long (more than " + std::to_string(kMaxTokens) + " tokens)");
    bool matched = false;
    for (const char* op : kOps) {
      const size_t n = std::strlen(op);
      if (s.compare(k, n, op) == 0) {
        tokens.push_back(Token{Token::Kind::kOp, op, {}});
        k += n;
        matched = true;
        break;
      }
    }
    if (!matched) SyntaxError();
  }
  tokens.push_back(Token{});
  return tokens;
}

}  // namespace urdfsnap::xacro
