// The Python expression subset: values and spelling of results, Python's operator semantics,
// builtins and math, and the errors Python raises (including the __ guard).
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

#include "xacro/internal/builtins.h"
#include "xacro/internal/evaluation_budget.h"
#include "xacro/internal/expression_evaluator.h"
#include "xacro/internal/expression_parser.h"

namespace urdfsnap::xacro {
namespace {

class Names : public NameLookup {
 public:
  Names() : globals_(MakeGlobalSymbols({}, {}, [this](const std::string& w) { warnings.push_back(w); })) {
    locals_["x"] = Value::Integer(3);
    locals_["name"] = Value::Str("gripper_left");
    locals_["xyz"] = Value::List({Value::Float(0.1), Value::Float(0.2), Value::Float(0.3)});
  }
  Value Lookup(const std::string& name) override {
    if (auto it = locals_.find(name); it != locals_.end()) return it->second;
    if (auto it = globals_.find(name); it != globals_.end()) return it->second;
    throw EvalError("name '" + name + "' is not defined");
  }
  std::vector<std::string> warnings;

 private:
  std::unordered_map<std::string, Value> globals_;
  std::map<std::string, Value> locals_;
};

std::string Eval(const std::string& text) {
  Names names;
  return ToStr(Evaluate(*ParseExpression(text), names));
}

std::string EvalFailure(const std::string& text) {
  try {
    Eval(text);
  } catch (const EvalError& e) {
    return e.what();
  }
  return "(no error)";
}

struct Case {
  const char* expr;
  const char* expected;
};

TEST(Expression, Arithmetic) {
  const Case cases[] = {
      {"1 + 2", "3"}, {"10 - 4.5", "5.5"}, {"10 / 4", "2.5"}, {"10 / 2", "5.0"}, {"7 // 2", "3"},
      {"-7 // 2", "-4"}, {"7 % 3", "1"}, {"-7 % 3", "2"}, {"7 % -3", "-2"}, {"7.5 % 2", "1.5"},
      {"-7.5 // 2", "-4.0"}, {"2 ** 10", "1024"}, {"2 ** -1", "0.5"}, {"-2 ** 2", "-4"},
      {"(-2) ** 2", "4"}, {"2 + 3 * 4 ** 2", "50"}, {"2 ** 64", "18446744073709551616"},
      {"10 ** 20", "100000000000000000000"}, {"1_000 + 1", "1001"}, {"0x10 + 0o17 + 0b101", "36"},
      {"True * 3", "3"}, {"3 * 0.5", "1.5"}, {"0.1 + 0.2", "0.30000000000000004"}, {"1e-7", "1e-07"},
      {"-(-3)", "3"}, {"~5", "-6"}, {"6 & 3 | 8 ^ 1", "11"}, {"1 << 4", "16"}, {"12 / 4", "3.0"},
  };
  for (const auto& c : cases) EXPECT_EQ(Eval(c.expr), c.expected) << c.expr;
}

TEST(Expression, ComparisonsAndLogic) {
  const Case cases[] = {
      {"1 < 2 < 3", "True"}, {"1 < 3 < 2", "False"}, {"x == 3.0", "True"}, {"0 or 'a'", "a"},
      {"'' and 1", ""}, {"1 and [] or 5", "5"}, {"not x", "False"}, {"'left' in name", "True"},
      {"4 not in xyz", "True"}, {"None is None", "True"}, {"x is not None", "True"},
      {"'gpu' if x > 2 else 'cpu'", "gpu"}, {"'a' if 0 else ('b' if 1 else 'c')", "b"},
      {"[1, 2] < [1, 3]", "True"}, {"'abc' < 'abd'", "True"}, {"True == 1", "True"},
  };
  for (const auto& c : cases) EXPECT_EQ(Eval(c.expr), c.expected) << c.expr;
}

TEST(Expression, StringsListsDicts) {
  const Case cases[] = {
      {"name + '_x'", "gripper_left_x"}, {"'ab' * 3", "ababab"}, {"name.upper()", "GRIPPER_LEFT"},
      {"'a-b-c'.replace('-', '_')", "a_b_c"}, {"'%s_%d' % ('p', 3)", "p_3"}, {"'%.3f' % (1/3)", "0.333"},
      {"'%g' % 0.0001", "0.0001"}, {"'%.2e' % 12345.678", "1.23e+04"}, {"'%d' % 3.7", "3"},
      {"'%5s|%-4d|%03d' % ('a', 7, 5)", "    a|7   |005"}, {"'%(k)s' % dict(k=1)", "1"},
      {"'a b c'.split()[1]", "b"}, {"'a,b,,c'.split(',')", "['a', 'b', '', 'c']"},
      {"'/'.join(['x', 'y'])", "x/y"}, {"name[1:3]", "ri"}, {"name[::-1][:4]", "tfel"},
      {"name[-4:]", "left"}, {"'  pad '.strip()", "pad"}, {"\"dq\" 'concat'", "dqconcat"},
      {"'it\\'s'", "it's"}, {"python.repr('it\\'s')", "\"it's\""}, {"str(1.5) + 'm'", "1.5m"},
      {"name.startswith(('arm', 'grip'))", "True"}, {"'x'.join('abc')", "axbxc"},
      {"xyz", "[0.1, 0.2, 0.3]"}, {"xyz[-1]", "0.3"}, {"xyz[1:]", "[0.2, 0.3]"}, {"(1,)", "(1,)"},
      {"(1, 2)", "(1, 2)"}, {"[]", "[]"}, {"[[1, 2], [3, 4]][1][0]", "3"},
      {"[v * 2 for v in xyz]", "[0.2, 0.4, 0.6]"}, {"[a + b for a, b in [(1, 2), (3, 4)]]", "[3, 7]"},
      {"[i for i in python.range(6) if i % 2 if i > 1]", "[3, 5]"},
      {"[(i, j) for i in [1, 2] for j in 'ab']", "[(1, 'a'), (1, 'b'), (2, 'a'), (2, 'b')]"},
      {"dict(lower=-1.57, upper=1.57)", "{'lower': -1.57, 'upper': 1.57}"},
      {"dict(a=1)['a']", "1"}, {"list(dict(a=1, b=2).keys())", "['a', 'b']"},
      {"dict(a=1).get('z', 9)", "9"}, {"len(name)", "12"}, {"len('é')", "1"},
      {"python.sum(x for x in xyz)", "0.6000000000000001"}, {"sorted([3, 1, 2])", "[1, 2, 3]"},
      {"python.sorted([3, 1, 2], reverse=True)", "[3, 2, 1]"}, {"list(map(str, [1, 2]))", "['1', '2']"},
      {"list(python.zip([1, 2], 'ab'))", "[(1, 'a'), (2, 'b')]"}, {"list(python.enumerate('ab'))", "[(0, 'a'), (1, 'b')]"},
      {"python.any([0, 1])", "True"}, {"python.abs(-2)", "2"}, {"python.divmod(-7, 2)", "(-4, 1)"},
  };
  for (const auto& c : cases) EXPECT_EQ(Eval(c.expr), c.expected) << c.expr;
}

TEST(Expression, BuiltinsAndMath) {
  const Case cases[] = {
      {"pi", "3.141592653589793"}, {"math.pi", "3.141592653589793"}, {"tau", "6.283185307179586"},
      {"e", "2.718281828459045"}, {"sin(0)", "0.0"}, {"sin(pi)", "1.2246467991473532e-16"},
      {"radians(180)", "3.141592653589793"}, {"degrees(pi)", "180.0"}, {"sqrt(16)", "4.0"},
      {"floor(2.7)", "2"}, {"ceil(2.1)", "3"}, {"math.floor(-0.5)", "-1"}, {"atan2(1, 1)", "0.7853981633974483"},
      {"hypot(3, 4)", "5.0"}, {"pow(2, 3)", "8.0"}, {"fabs(-2)", "2.0"}, {"log(e)", "1.0"},
      {"log(8, 2)", "3.0"}, {"round(2.675, 2)", "2.67"}, {"round(2.5)", "2"}, {"round(3.5)", "4"},
      {"round(-0.5)", "0"}, {"round(7.0)", "7"}, {"int('42') + int(3.9)", "45"}, {"int(-2.9)", "-2"},
      {"float('1.25')", "1.25"}, {"float('inf')", "inf"}, {"min(3, 1, 2)", "1"}, {"max(xyz)", "0.3"},
      {"str(True)", "True"}, {"inf", "inf"}, {"math.isclose(0.1 + 0.2, 0.3)", "True"},
      {"math.factorial(25)", "15511210043330985984000000"},
  };
  for (const auto& c : cases) EXPECT_EQ(Eval(c.expr), c.expected) << c.expr;
}

// Expressions checked against Python 3.11's own eval() (same globals as xacro's): every result
// must be spelt as Python's str() spells it.
TEST(Expression, AgreesWithPython) {
  const Case cases[] = {
      {"'a,b,,c'.split(',', 1)", "['a', 'b,,c']"},
      // found by fuzzing: an empty sequence repeated 10^12 times looped 10^12 times
      {"[] * 9 * 1000000000000", "[]"},
      {"len('' * 10**15)", "0"},
      {"'a b  c d'.split(None, 2)", "['a', 'b', 'c d']"},
      {"'a b  c d'.rsplit(None, 1)", "['a b  c', 'd']"},
      {"'a,b,c'.rsplit(',', 1)", "['a,b', 'c']"},
      {"'  x  y '.split()", "['x', 'y']"},
      {"'abc'.center(8, '*')", "**abc***"},
      {"'abc'.center(7)", "  abc  "},
      {"'-42'.zfill(6)", "-00042"},
      {"'hello world'.title()", "Hello World"},
      {"'Hello'.swapcase()", "hELLO"},
      {"'%5.2f|%-8s|%+d|% d' % (3.14159, 'ab', 5, 7)", " 3.14|ab      |+5| 7"},
      {"'%x %X %o %e %E %G' % (255, 255, 8, 0.5, 12345.678, 1e-10)", "ff FF 10 5.000000e-01 1.234568E+04 1E-10"},
      {"'%r %s' % ('q', [1, 'a'])", "'q' [1, 'a']"},
      {"'%%d' % ()", "%d"},
      {"'%c%c' % (65, 'b')", "Ab"},
      {"'%.3s' % 'abcdef'", "abc"},
      {"'%10.4e' % 1234.5", "1.2345e+03"},
      {"'%-+8.2f|' % 2.5", "+2.50   |"},
      {"'%05d' % -42", "-0042"},
      {"'%i' % True", "1"},
      {"round(0.5)", "0"},
      {"round(1.5)", "2"},
      {"round(-1.5)", "-2"},
      {"round(2.675, 2)", "2.67"},
      {"round(1234.5678, -2)", "1200.0"},
      {"round(5, -1)", "0"},
      {"round(15, -1)", "20"},
      {"round(0.1 + 0.2, 10)", "0.3"},
      {"int('  -12  ')", "-12"},
      {"float('  1e-3 ')", "0.001"},
      {"float('-inf')", "-inf"},
      {"str(1e300 * 10)", "1e+301"},
      {"str(-0.0 * 1)", "-0.0"},
      {"1e308 * 10 - 1e308 * 10 == 1e308 * 10 - 1e308 * 10", "False"},
      {"7 // -2", "-4"},
      {"-7 % -3", "-1"},
      {"7.0 // -2", "-4.0"},
      {"-7.5 % 2", "0.5"},
      {"2 ** 0.5", "1.4142135623730951"},
      {"(-8) ** 2", "64"},
      {"10 ** -2", "0.01"},
      {"python.abs(-0.0)", "0.0"},
      {"python.divmod(7.5, 2)", "(3.0, 1.5)"},
      {"max('abc', 'abd')", "abd"},
      {"min([3, 1], [2, 5])", "[2, 5]"},
      {"python.sorted(['b', 'A', 'a'])", "['A', 'a', 'b']"},
      {"list(python.reversed([1, 2, 3]))", "[3, 2, 1]"},
      {"[x * y for x in python.range(3) for y in python.range(x) if x != y]", "[0, 0, 2]"},
      {"dict(python.zip(['a', 'b'], [1, 2]))", "{'a': 1, 'b': 2}"},
      {"dict([('k', 1)], z=2)", "{'k': 1, 'z': 2}"},
      {"list(dict(a=1, b=2).items())", "[('a', 1), ('b', 2)]"},
      {"len(dict(a=1))", "1"},
      {"'abc'[::2]", "ac"},
      {"'abcdef'[-2:1:-1]", "edc"},
      {"[1, 2, 3, 4, 5][::-2]", "[5, 3, 1]"},
      {"[1, 2, 3][5:]", "[]"},
      {"(1, 2, 3)[1:]", "(2, 3)"},
      {"'x' in ['x', 'y']", "True"},
      {"[1, 2] + [3]", "[1, 2, 3]"},
      {"(1,) * 3", "(1, 1, 1)"},
      {"[0] * 3", "[0, 0, 0]"},
      {"'ab' < 'b'", "True"},
      {"(1, 2) < (1, 2, 0)", "True"},
      {"1 < 2.5 <= 2.5", "True"},
      {"not []", "True"},
      {"0 and 1", "0"},
      {"None", "None"},
      {"True + True", "2"},
      {"3 / 2 * 2", "3.0"},
      {"1 / 3 * 3", "1.0"},
      {"0.1 * 3", "0.30000000000000004"},
      {"1e16 + 1", "1e+16"},
      {"2 ** 62", "4611686018427387904"},
      {"-2 ** 63", "-9223372036854775808"},
      {"4.0 ** 0.5", "2.0"},
      {"float(10 ** 15)", "1000000000000000.0"},
      {"float(10 ** 16)", "1e+16"},
      {"1e-4 * 1", "0.0001"},
      {"123456789012345678", "123456789012345678"},
      {"0.000123", "0.000123"},
      {"1.5e300 * 1.5e300", "inf"},
      {"python.sum([0.1] * 10)", "0.9999999999999999"},
      {"sin(pi / 6)", "0.49999999999999994"},
      {"cos(pi / 3)", "0.5000000000000001"},
      {"atan(1) * 4", "3.141592653589793"},
      {"exp(1)", "2.718281828459045"},
      {"log10(1000)", "3.0"},
      {"log2(8)", "3.0"},
      {"sqrt(2) * sqrt(2)", "2.0000000000000004"},
      {"degrees(1)", "57.29577951308232"},
      {"radians(1)", "0.017453292519943295"},
      {"hypot(1, 1)", "1.4142135623730951"},
      {"fmod(-7, 3)", "-1.0"},
      {"copysign(1, -0.0)", "-1.0"},
      {"floor(-2.5)", "-3"},
      {"ceil(-2.5)", "-2"},
      {"trunc(-2.7)", "-2"},
      {"pow(2, 0.5)", "1.4142135623730951"},
      {"tan(pi / 4)", "0.9999999999999999"},
      {"acos(0.5)", "1.0471975511965979"},
      {"isinf(inf)", "True"},
      {"math.gcd(12, 18)", "6"},
      {"math.factorial(10)", "3628800"},
      {"math.isqrt(17)", "4"},
      {"math.e ** 2", "7.3890560989306495"},
      {"tau / 2", "3.141592653589793"},
  };
  for (const auto& c : cases) EXPECT_EQ(Eval(c.expr), c.expected) << c.expr;
}

TEST(Expression, DeprecatedDirectNamesWarn) {
  Names names;
  EXPECT_EQ(ToStr(Evaluate(*ParseExpression("range(3)"), names)), "range(0, 3)");
  ASSERT_EQ(names.warnings.size(), 1u);
  EXPECT_EQ(names.warnings[0], "Using range() directly is deprecated. Use python.range() instead.");
}

TEST(Expression, ErrorsArePythonsErrors) {
  const Case cases[] = {
      {"1 / 0", "division by zero"},
      // found by fuzzing: the width overflowed an int (Python runs out of memory instead)
      {"'%-7777777777777d' % 2", "width or precision too big"},
      {"'%*d' % (10**12, 2)", "width or precision too big"},
      {"1 // 0", "integer division or modulo by zero"},
      {"1.0 / 0", "float division by zero"},
      {"undefined_name", "name 'undefined_name' is not defined"},
      {"true", "name 'true' is not defined"},
      {"1 +* 2", "invalid syntax (<expression>, line 1)"},
      {" {'a': 1", "invalid syntax (<expression>, line 1)"},
      {"007", "leading zeros in decimal integer literals are not permitted (<expression>, line 1)"},
      {"__import__('os').getcwd()", "Use of invalid name(s): __import__"},
      {"().__class__", "Use of invalid name(s): __class__"},
      {"'a' + 1", "can only concatenate str (not \"int\") to str"},
      {"'a' < 1", "'<' not supported between instances of 'str' and 'int'"},
      {"xyz[5]", "list index out of range"},
      {"dict(a=1)['b']", "'b'"},
      {"x()", "'int' object is not callable"},
      {"name.nosuch", "'str' object has no attribute 'nosuch'"},
      {"math.nosuch", "module 'math' has no attribute 'nosuch'"},
      {"sqrt(-1)", "math domain error"},
      {"int('x')", "invalid literal for int() with base 10: 'x'"},
      {"'a' * 10 ** 12", "result of repetition is too large (limit 16777216)"},
      {"2 ** 200", "integer overflow: the result needs more than 127 bits"},
      {"lambda: 1", "lambda expressions are not supported"},
  };
  for (const auto& c : cases) EXPECT_EQ(EvalFailure(c.expr), c.expected) << c.expr;
}

// Lists are bounded before they are built, and all an expression builds is bounded in all, so no
// expression can take gigabytes or minutes (found by fuzzing: a filtered comprehension over
// range(10**28) asked malloc for 2.4 GB before "range() too large").
TEST(Expression, ListsAreBoundedBeforeTheyAreBuilt) {
  const Case cases[] = {
      {"[i for i in python.range(55555555555555555555555555556) if i % 2 if i //1]",
       "range() too large: 55555555555555555555555555556 items (the limit is 1048576)"},
      {"len([i for i in python.range(100000000) if i % 2])",
       "range() too large: 100000000 items (the limit is 1048576)"},
      {"python.range(-2**126, 2**126)", "range() too large: its length does not fit in 127 bits"},
      {"[c for c in 'a' * 2000000]", "string to iterate too large: 2000000 items (the limit is 1048576)"},
      {"[0] * 2000000", "result of repetition is too large (limit 1048576)"},
      {"[0 for i in python.range(4000) for j in python.range(4000) if 0]",
       "expressions build more than 4194304 list items in all (runaway comprehension or range()?)"},
      {"[list(python.range(1000000)) for i in python.range(10)]",
       "expressions make lists, tuples and dicts of more than 1048576 items in all (runaway comprehension?)"},
      // a million small lists of long strings, each list made by a method (1.2 GB before; found
      // by fuzzing)
      {"len([('a b c d ' * 25).split(None, 3) for i in python.range(1000) for j in python.range(1000)])",
       "expressions make lists, tuples and dicts of more than 1048576 items in all (runaway comprehension?)"},
  };
  for (const auto& c : cases) EXPECT_EQ(EvalFailure(c.expr), c.expected) << c.expr;
  {
    // one list's limit, with budget to spare for the two halves
    const EvaluationBudget roomy(kEvaluationBudgetItems, kEvaluationBudgetBytes, size_t{4} << 20);
    EXPECT_EQ(EvalFailure("list(python.range(1000000)) + list(python.range(1000000))"),
              "concatenated sequence too large: 2000000 items (the limit is 1048576)");
  }
  // what fits is exact
  EXPECT_EQ(Eval("len(python.range(1048576))"), "1048576");
  EXPECT_EQ(Eval("list(python.range(10, 0, -3))"), "[10, 7, 4, 1]");
  EXPECT_EQ(Eval("list(python.range(-5, 5, 4))"), "[-5, -1, 3]");
  EXPECT_EQ(Eval("list(python.range(5, 5))"), "[]");
  EXPECT_EQ(Eval("python.sum([i for i in python.range(1000) for j in python.range(1000) if j == 0])"), "499500");
}

// Strings are bounded before they are built, and the text all expressions build is bounded in
// all, so that no expression takes gigabytes (before, a property that doubled the previous one,
// thirty deep, passed 6 GB). Copying a string value shares its text.
TEST(Expression, StringsAreBoundedBeforeTheyAreBuilt) {
  const Case cases[] = {
      {"'ab' * 2**23 + 'ab' * 2**23", "concatenated string too large: 33554432 bytes (the limit is 16777216)"},
      {"''.join(['ab' * 2**23, 'x'])", "joined string too large: 16777217 bytes (the limit is 16777216)"},
      {"('ab' * 2**22).replace('a', 'aaaa')", "replaced string too large: 20971520 bytes (the limit is 16777216)"},
      {"'%s%s%s' % ('ab' * 2**22, 'ab' * 2**22, 'a')", "formatted string too large: 16777217 bytes (the limit is 16777216)"},
      {"'a'.ljust(10**9)", "padded string too large: 1000000000 bytes (the limit is 16777216)"},
      {"'a'.zfill(10**9)", "padded string too large: 1000000000 bytes (the limit is 16777216)"},
      // a repr stops at the first piece that takes it past the limit
      {"str(['ab' * 2**22] * 3)", "repr too large: 16777223 bytes (the limit is 16777216)"},
      {"python.repr(python.set(['a' * 9000000, 'b' * 9000000]))", "repr too large: 18000007 bytes (the limit is 16777216)"},
      {"len([('a' * 9000000).upper() for i in python.range(100)])",
       "expressions build more than 268435456 bytes of text in all (runaway string building?)"},
      {"len([('a' * 9000000)[1:] for i in python.range(100)])",
       "expressions build more than 268435456 bytes of text in all (runaway string building?)"},
  };
  for (const auto& c : cases) EXPECT_EQ(EvalFailure(c.expr), c.expected) << c.expr;
  // copies of a value share its text: a thousand of them cost no more than one
  EXPECT_EQ(Eval("len([('a' * 9000000)] * 1000 + [s for s in ['a' * 9000000] for i in python.range(1000)])"), "2000");
  EXPECT_EQ(Eval("len(str('a' * 9000000))"), "9000000");
}

TEST(Expression, NestingIsBounded) {
  EXPECT_EQ(EvalFailure(std::string(1000, '(') + "1" + std::string(1000, ')')),
            "too many nested parentheses (<expression>, line 1)");
  std::string chain = "1";
  for (int k = 0; k < 15000; ++k) chain += "+1";
  EXPECT_EQ(EvalFailure(chain), "expression too long (more than 20000 tokens)");
  std::string ok = "1";
  for (int k = 0; k < 1000; ++k) ok += "+1";
  EXPECT_EQ(Eval(ok), "1001");
}

}  // namespace
}  // namespace urdfsnap::xacro
