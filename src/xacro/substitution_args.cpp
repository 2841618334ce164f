// Substitution args as xacro's substitution_args.py resolves them.
#include "xacro/internal/substitution_args.h"

#include <unistd.h>

#include <cstdlib>
#include <sstream>
#include <vector>

#include "common/error.h"
#include "xacro/internal/expression_evaluator.h"
#include "xacro/internal/expression_parser.h"

namespace urdfsnap::xacro {
namespace {

[[noreturn]] void Fail(const std::string& message) {
  // the reference prints the exception class and repeats the message
  throw EvalError("<class 'xacro.substitution_args.SubstitutionException'>: " + message + " " + message);
}

std::string CurrentDirectory() {
  std::vector<char> buf(4096);
  if (!getcwd(buf.data(), buf.size())) Fail("cannot read the current directory");
  return buf.data();
}

std::string Arg(const std::string& name, const SubstitutionContext& context) {
  auto it = context.args.find(name);
  if (it == context.args.end()) throw EvalError("Undefined substitution argument " + name);
  return it->second;
}

std::string Find(const std::string& package, const SubstitutionContext& context) {
  try {
    return FindPackage(package, context.packages);
  } catch (const Error& e) {
    throw EvalError(std::string("<class 'PackageNotFoundError'>: ") + e.what());
  }
}

// roslaunch's convert_value(value, 'auto')
Value AutoValue(const std::string& value) {
  char* end = nullptr;
  if (value.find('.') != std::string::npos) {
    const double f = std::strtod(value.c_str(), &end);
    if (!value.empty() && end && *end == '\0') return Value::Float(f);
  } else {
    const long long i = std::strtoll(value.c_str(), &end, 10);
    if (!value.empty() && end && *end == '\0') return Value::Integer(i);
  }
  std::string lower = value;
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (lower == "true" || lower == "false") return Value::Bool(lower == "true");
  return Value::Str(value);
}

class EvalNames : public NameLookup {
 public:
  explicit EvalNames(const SubstitutionContext& context) : context_(context) {}

  Value Lookup(const std::string& name) override {
    if (name == "true" || name == "True") return Value::Bool(true);
    if (name == "false" || name == "False") return Value::Bool(false);
    if (name == "arg") {
      return Value::Callable("arg", [this](ValueList& a, Kwargs&) {
        if (a.size() != 1 || a[0].type != Value::Type::kStr) throw EvalError("arg() takes one name");
        return AutoValue(Arg(a[0].s, context_));
      });
    }
    if (name == "env" || name == "optenv" || name == "find") {
      return Value::Callable(name, [this, name](ValueList& a, Kwargs&) {
        if (a.empty() || a[0].type != Value::Type::kStr) throw EvalError(name + "() takes a name");
        if (name == "find") return Value::Str(Find(a[0].s, context_));
        const char* v = std::getenv(a[0].s.c_str());
        if (v) return Value::Str(v);
        if (name == "env") Fail("environment variable '" + a[0].s + "' is not set");
        return a.size() > 1 ? a[1] : Value::Str("");
      });
    }
    if (name == "dirname") {
      return Value::Callable(name, [](ValueList&, Kwargs&) -> Value {
        Fail("Cannot substitute $(dirname),no file/directory information available.");
      });
    }
    static const char* const kBuiltins[] = {"list", "dict", "map", "str", "float", "int"};
    const auto& globals = *context_.globals;
    const Value& math = globals.at("math");
    for (const auto& [key, value] : math.dict->items) {
      if (key.s == name) return value;
    }
    for (const char* b : kBuiltins) {
      if (name == b) return globals.at(name);
    }
    auto it = context_.args.find(name);
    if (it == context_.args.end()) throw EvalError("name '" + name + "' is not defined");
    return AutoValue(it->second);
  }

 private:
  const SubstitutionContext& context_;
};

// _collect_args: the contents of every $(...) in `text`
std::vector<std::string> CollectArgs(const std::string& text) {
  enum { kOut, kDollar, kLeftParen, kIn } state = kOut;
  std::vector<std::string> args;
  std::string buffer;
  for (char c : text) {
    if (c == '$') {
      if (state == kOut) state = kDollar;
      else if (state != kDollar) Fail("Dollar signs \"$\" cannot be inside of substitution args [" + text + "]");
    } else if (c == '(') {
      if (state == kDollar) state = kLeftParen;
      else if (state != kOut) Fail("Invalid left parenthesis \"(\" in substitution args [" + text + "]");
    } else if (c == ')') {
      if (state == kIn) args.push_back(buffer);
      buffer.clear();
      state = kOut;
    } else if (state == kDollar) {
      state = kOut;
    } else if (state == kLeftParen) {
      state = kIn;
    }
    if (state == kIn) buffer += c;
  }
  return args;
}

std::string ReplaceAll(std::string s, const std::string& from, const std::string& to) {
  for (size_t k = s.find(from); k != std::string::npos; k = s.find(from, k + to.size())) s.replace(k, from.size(), to);
  return s;
}

std::string ResolvePass(const std::string& text, const SubstitutionContext& context, bool find_only) {
  std::string resolved = text;
  for (const std::string& a : CollectArgs(text)) {
    std::istringstream words(a);
    std::vector<std::string> split;
    for (std::string w; words >> w;) split.push_back(w);
    if (split.empty()) Fail("Unknown substitution command [" + a + "]. Valid commands are ['find', 'env', 'optenv', 'dirname', 'arg']");
    const std::string& command = split[0];
    const std::vector<std::string> args(split.begin() + 1, split.end());
    std::string value;
    if (command == "find") {
      if (args.size() != 1) Fail("$(find pkg) accepts exactly one argument [" + a + "]");
      value = Find(args[0], context);
    } else if (find_only) {
      continue;
    } else if (command == "env") {
      if (args.size() != 1) Fail("$(env var) command only accepts one argument [" + a + "]");
      const char* v = std::getenv(args[0].c_str());
      if (!v) Fail("environment variable '" + args[0] + "' is not set");
      value = v;
    } else if (command == "optenv") {
      if (args.empty()) Fail("$(optenv var) must specify an environment variable [" + a + "]");
      const char* v = std::getenv(args[0].c_str());
      if (v) {
        value = v;
      } else {
        for (size_t k = 1; k < args.size(); ++k) value += (k > 1 ? " " : "") + args[k];
      }
    } else if (command == "dirname") {
      Fail("Cannot substitute $(dirname),no file/directory information available.");
    } else if (command == "arg") {
      if (args.empty()) Fail("$(arg var) must specify a variable name [" + a + "]");
      if (args.size() > 1) Fail("$(arg var) may only specify one arg [" + a + "]");
      value = Arg(args[0], context);
    } else {
      Fail("Unknown substitution command [" + a + "]. Valid commands are ['find', 'env', 'optenv', 'dirname', 'arg']");
    }
    resolved = ReplaceAll(resolved, "$(" + a + ")", value);
  }
  return resolved;
}

}  // namespace

std::string ResolveSubstitution(const std::string& text, const SubstitutionContext& context) {
  if (text == "$(cwd)") return CurrentDirectory();
  if (text.empty()) return text;
  if (text.rfind("$(eval ", 0) == 0 && text.back() == ')') {
    const std::string expr = text.substr(7, text.size() - 8);
    if (expr.find("__") != std::string::npos) Fail("$(eval ...) may not contain double underscore expressions");
    EvalNames names(context);
    return ToStr(Evaluate(*ParseExpression(expr), names));
  }
  return ResolvePass(ResolvePass(text, context, false), context, true);
}

}  // namespace urdfsnap::xacro
