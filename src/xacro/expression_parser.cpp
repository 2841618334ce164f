// Recursive-descent parser for the Python expression subset, following Python's grammar rules.
#include "xacro/internal/expression_parser.h"

#include <set>

#include "xacro/internal/expression_lexer.h"

namespace urdfsnap::xacro {
namespace {

// Python's parser refuses deeply nested expressions too; the limit keeps the stack bounded
constexpr int kMaxNesting = 200;

class NestingGuard {
 public:
  explicit NestingGuard(int& depth) : depth_(depth) {
    if (++depth_ > kMaxNesting) {
      --depth_;
      throw EvalError("too many nested parentheses (<expression>, line 1)");
    }
  }
  ~NestingGuard() { --depth_; }
  NestingGuard(const NestingGuard&) = delete;
  NestingGuard& operator=(const NestingGuard&) = delete;

 private:
  int& depth_;
};

class Parser {
 public:
  explicit Parser(std::vector<Token> tokens) : tokens_(std::move(tokens)) {}

  ExprPtr ParseAll() {
    ExprPtr e = ParseTestList();
    if (Peek().kind != Token::Kind::kEnd) Fail();
    if (!invalid_.empty()) {
      std::string names;
      for (const std::string& n : invalid_) names += (names.empty() ? "" : ", ") + n;
      throw EvalError("Use of invalid name(s): " + names);
    }
    return e;
  }

 private:
  [[noreturn]] void Fail() { throw EvalError("invalid syntax (<expression>, line 1)"); }

  const Token& Peek(size_t ahead = 0) const { return tokens_[std::min(pos_ + ahead, tokens_.size() - 1)]; }
  bool IsOp(const char* op, size_t ahead = 0) const {
    return Peek(ahead).kind == Token::Kind::kOp && Peek(ahead).text == op;
  }
  bool IsKeyword(const char* kw, size_t ahead = 0) const {
    return Peek(ahead).kind == Token::Kind::kName && Peek(ahead).text == kw;
  }
  bool Accept(const char* op) {
    if (!IsOp(op)) return false;
    ++pos_;
    return true;
  }
  bool AcceptKeyword(const char* kw) {
    if (!IsKeyword(kw)) return false;
    ++pos_;
    return true;
  }
  void Expect(const char* op) {
    if (!Accept(op)) Fail();
  }

  static ExprPtr Make(Expr::Kind kind) {
    auto e = std::make_unique<Expr>();
    e->kind = kind;
    return e;
  }

  // Python's keywords: not names (`python.True` is a syntax error too)
  static bool IsReserved(const std::string& name) {
    static const std::set<std::string> kKeywords = {"and", "or", "not", "in", "is", "if", "else", "for",
                                                    "lambda", "import", "def", "class", "return", "yield",
                                                    "from", "with", "as", "del", "pass", "while", "await",
                                                    "async", "global", "True", "False", "None"};
    return kKeywords.count(name) != 0;
  }

  void NoteName(const std::string& name) {
    if (name.size() >= 2 && name[0] == '_' && name[1] == '_') invalid_.insert(name);
  }

  // testlist: test (',' test)* [','] -> a tuple when a comma appears
  ExprPtr ParseTestList() {
    ExprPtr first = ParseTest();
    if (!IsOp(",")) return first;
    auto tuple = Make(Expr::Kind::kTuple);
    tuple->kids.push_back(std::move(first));
    while (Accept(",")) {
      if (AtExpressionEnd()) break;
      tuple->kids.push_back(ParseTest());
    }
    return tuple;
  }

  bool AtExpressionEnd() const {
    const Token& t = Peek();
    return t.kind == Token::Kind::kEnd ||
           (t.kind == Token::Kind::kOp && (t.text == ")" || t.text == "]" || t.text == "}" || t.text == "="));
  }

  ExprPtr ParseTest() {
    const NestingGuard guard(depth_);
    if (IsKeyword("lambda")) throw EvalError("lambda expressions are not supported");
    ExprPtr body = ParseOr();
    if (!AcceptKeyword("if")) return body;
    auto e = Make(Expr::Kind::kIfElse);
    e->kids.push_back(std::move(body));
    e->kids.push_back(ParseOr());
    if (!AcceptKeyword("else")) Fail();
    e->kids.push_back(ParseTest());
    return e;
  }

  ExprPtr ParseOr() { return ParseBool("or", Expr::Kind::kOr, &Parser::ParseAnd); }
  ExprPtr ParseAnd() { return ParseBool("and", Expr::Kind::kAnd, &Parser::ParseNot); }

  ExprPtr ParseBool(const char* kw, Expr::Kind kind, ExprPtr (Parser::*next)()) {
    ExprPtr first = (this->*next)();
    if (!IsKeyword(kw)) return first;
    auto e = Make(kind);
    e->kids.push_back(std::move(first));
    while (AcceptKeyword(kw)) e->kids.push_back((this->*next)());
    return e;
  }

  ExprPtr ParseNot() {
    if (!AcceptKeyword("not")) return ParseComparison();
    auto e = Make(Expr::Kind::kUnary);
    e->name = "not";
    e->kids.push_back(ParseNot());
    return e;
  }

  bool ReadCompareOp(std::string& op) {
    static const char* const kOps[] = {"<", ">", "==", ">=", "<=", "!="};
    for (const char* o : kOps) {
      if (Accept(o)) {
        op = o;
        return true;
      }
    }
    if (AcceptKeyword("in")) {
      op = "in";
      return true;
    }
    if (IsKeyword("not") && IsKeyword("in", 1)) {
      pos_ += 2;
      op = "not in";
      return true;
    }
    if (AcceptKeyword("is")) {
      op = AcceptKeyword("not") ? "is not" : "is";
      return true;
    }
    return false;
  }

  ExprPtr ParseComparison() {
    ExprPtr first = ParseBinary(0);
    std::string op;
    if (!ReadCompareOp(op)) return first;
    auto e = Make(Expr::Kind::kCompare);
    e->kids.push_back(std::move(first));
    do {
      e->ops.push_back(op);
      e->kids.push_back(ParseBinary(0));
    } while (ReadCompareOp(op));
    return e;
  }

  // binary operator levels, loosest first: | ^ & shifts additive multiplicative
  ExprPtr ParseBinary(int level) {
    static const std::vector<std::vector<std::string>> kLevels = {
        {"|"}, {"^"}, {"&"}, {"<<", ">>"}, {"+", "-"}, {"*", "/", "//", "%"}};
    if (level == static_cast<int>(kLevels.size())) return ParseUnary();
    ExprPtr left = ParseBinary(level + 1);
    while (true) {
      const std::string* found = nullptr;
      for (const std::string& op : kLevels[level]) {
        if (IsOp(op.c_str())) found = &op;
      }
      if (!found) return left;
      ++pos_;
      auto e = Make(Expr::Kind::kBinary);
      e->name = *found;
      e->kids.push_back(std::move(left));
      e->kids.push_back(ParseBinary(level + 1));
      left = std::move(e);
    }
  }

  ExprPtr ParseUnary() {
    const NestingGuard guard(depth_);
    for (const char* op : {"-", "+", "~"}) {
      if (Accept(op)) {
        auto e = Make(Expr::Kind::kUnary);
        e->name = op;
        e->kids.push_back(ParseUnary());
        return e;
      }
    }
    return ParsePower();
  }

  ExprPtr ParsePower() {
    ExprPtr base = ParsePrimary();
    if (!Accept("**")) return base;
    auto e = Make(Expr::Kind::kBinary);
    e->name = "**";
    e->kids.push_back(std::move(base));
    e->kids.push_back(ParseUnary());
    return e;
  }

  ExprPtr ParsePrimary() {
    ExprPtr e = ParseAtom();
    while (true) {
      if (Accept(".")) {
        if (Peek().kind != Token::Kind::kName || IsReserved(Peek().text)) Fail();
        auto a = Make(Expr::Kind::kAttr);
        a->name = Peek().text;
        NoteName(a->name);
        ++pos_;
        a->kids.push_back(std::move(e));
        e = std::move(a);
      } else if (Accept("(")) {
        e = ParseCall(std::move(e));
      } else if (Accept("[")) {
        auto s = Make(Expr::Kind::kSubscript);
        s->kids.push_back(std::move(e));
        s->kids.push_back(ParseSubscript());
        Expect("]");
        e = std::move(s);
      } else {
        return e;
      }
    }
  }

  ExprPtr ParseCall(ExprPtr callee) {
    auto call = Make(Expr::Kind::kCall);
    call->kids.push_back(std::move(callee));
    while (!Accept(")")) {
      if (Peek().kind == Token::Kind::kName && IsOp("=", 1)) {
        call->ops.push_back(Peek().text);
        pos_ += 2;
        call->kids.push_back(ParseTest());
      } else {
        if (!call->ops.empty()) throw EvalError("positional argument follows keyword argument");
        ExprPtr arg = ParseTest();
        if (IsKeyword("for")) arg = ParseComprehension(std::move(arg));
        call->kids.push_back(std::move(arg));
      }
      if (!Accept(",")) {
        Expect(")");
        break;
      }
    }
    return call;
  }

  ExprPtr ParseSubscript() {
    ExprPtr start;
    if (!IsOp(":")) {
      start = ParseTest();
      if (!IsOp(":")) {
        if (!IsOp(",")) return start;
        auto tuple = Make(Expr::Kind::kTuple);
        tuple->kids.push_back(std::move(start));
        while (Accept(",") && !IsOp("]")) tuple->kids.push_back(ParseTest());
        return tuple;
      }
    }
    auto slice = Make(Expr::Kind::kSlice);
    slice->kids.resize(3);
    slice->kids[0] = std::move(start);
    Expect(":");
    if (!IsOp(":") && !IsOp("]")) slice->kids[1] = ParseTest();
    if (Accept(":") && !IsOp("]")) slice->kids[2] = ParseTest();
    return slice;
  }

  ExprPtr ParseComprehension(ExprPtr element) {
    auto comp = Make(Expr::Kind::kListComp);
    comp->kids.push_back(std::move(element));
    while (AcceptKeyword("for")) {
      ComprehensionClause clause;
      bool parenthesised = Accept("(");
      do {
        if (Peek().kind != Token::Kind::kName) Fail();
        clause.targets.push_back(Peek().text);
        NoteName(Peek().text);
        ++pos_;
      } while (Accept(",") && Peek().kind == Token::Kind::kName && !IsKeyword("in"));
      if (parenthesised) Expect(")");
      clause.unpack = clause.targets.size() > 1 || parenthesised;
      if (!AcceptKeyword("in")) Fail();
      clause.iter = ParseOr();
      while (AcceptKeyword("if")) clause.conditions.push_back(ParseOr());
      comp->clauses.push_back(std::move(clause));
    }
    return comp;
  }

  // the rest of "(...)" or "[...]" after the opening bracket: empty, a comprehension, a
  // parenthesised expression (no comma in round brackets), or the items of a tuple or list
  ExprPtr ParseDisplay(const char* close, Expr::Kind kind) {
    auto display = Make(kind);
    if (Accept(close)) return display;
    ExprPtr first = ParseTest();
    if (IsKeyword("for")) first = ParseComprehension(std::move(first));
    if (first->kind == Expr::Kind::kListComp || (kind == Expr::Kind::kTuple && IsOp(close))) {
      Expect(close);
      return first;
    }
    display->kids.push_back(std::move(first));
    while (Accept(",") && !IsOp(close)) display->kids.push_back(ParseTest());
    Expect(close);
    return display;
  }

  ExprPtr ParseAtom() {
    const Token& t = Peek();
    if (t.kind == Token::Kind::kNumber) {
      auto e = Make(Expr::Kind::kConst);
      e->constant = t.number;
      ++pos_;
      return e;
    }
    if (t.kind == Token::Kind::kString) {
      std::string text;
      while (Peek().kind == Token::Kind::kString) text += tokens_[pos_++].text;  // "a" "b" concatenates
      auto e = Make(Expr::Kind::kConst);
      e->constant = Value::Str(std::move(text));
      return e;
    }
    if (t.kind == Token::Kind::kName) {
      auto e = Make(Expr::Kind::kConst);
      if (t.text == "True" || t.text == "False") {
        e->constant = Value::Bool(t.text == "True");
      } else if (t.text == "None") {
        e->constant = Value::None();
      } else {
        if (IsReserved(t.text)) Fail();
        e->kind = Expr::Kind::kName;
        e->name = t.text;
        NoteName(t.text);
      }
      ++pos_;
      return e;
    }
    if (Accept("(")) return ParseDisplay(")", Expr::Kind::kTuple);
    if (Accept("[")) return ParseDisplay("]", Expr::Kind::kList);
    if (Accept("{")) {
      auto dict = Make(Expr::Kind::kDict);
      if (!IsOp("}")) {
        // a set display or comprehension: {a, b}, {x for x in y}
        ExprPtr first = ParseTest();
        if (IsKeyword("for")) {
          first = ParseComprehension(std::move(first));
          first->kind = Expr::Kind::kSetComp;
          Expect("}");
          return first;
        }
        if (!IsOp(":")) {
          auto set = Make(Expr::Kind::kSet);
          set->kids.push_back(std::move(first));
          while (Accept(",") && !IsOp("}")) set->kids.push_back(ParseTest());
          Expect("}");
          return set;
        }
        Expect(":");
        dict->kids.push_back(std::move(first));
        dict->kids.push_back(ParseTest());
        if (!Accept(",")) {
          Expect("}");
          return dict;
        }
      }
      while (!Accept("}")) {
        dict->kids.push_back(ParseTest());
        Expect(":");
        dict->kids.push_back(ParseTest());
        if (!Accept(",")) {
          Expect("}");
          break;
        }
      }
      return dict;
    }
    Fail();
  }

  std::vector<Token> tokens_;
  size_t pos_ = 0;
  int depth_ = 0;
  std::set<std::string> invalid_;
};

}  // namespace

ExprPtr ParseExpression(const std::string& text) { return Parser(Tokenize(text)).ParseAll(); }

}  // namespace urdfsnap::xacro
