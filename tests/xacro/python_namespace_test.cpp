// Every name of xacro's `python` namespace (create_global_symbols in ros/xacro's xacro/__init__.py,
// branch ros2: list dict map len str float int True False min max round abs all any complex divmod
// enumerate filter frozenset hash isinstance issubclass ord repr reversed slice set sum tuple type
// zip sorted range), which of them are also global, and the math functions Python 3.8 to 3.11
// added (xacro exposes all of math): each result spelt as Python's str()
// spells it and each error with Python's message. The expected texts are Python 3.11's own,
// printed by tests/xacro/python_expectations.py (PYTHONHASHSEED=0); addresses ("<zip object at
// 0x...>") differ from run to run and are compared without their digits.
#include <gtest/gtest.h>

#include <algorithm>
#include <regex>
#include <string>
#include <unordered_map>
#include <vector>

#include "xacro/internal/builtins.h"
#include "xacro/internal/evaluation_budget.h"
#include "xacro/internal/expression_evaluator.h"
#include "xacro/internal/expression_parser.h"

namespace urdfsnap::xacro {
namespace {

class Globals : public NameLookup {
 public:
  Globals() : globals_(MakeGlobalSymbols({}, {}, [this](const std::string& w) { warnings.push_back(w); })) {}
  Value Lookup(const std::string& name) override {
    if (auto it = globals_.find(name); it != globals_.end()) return it->second;
    throw EvalError("name '" + name + "' is not defined");
  }
  const std::unordered_map<std::string, Value>& all() const { return globals_; }
  std::vector<std::string> warnings;

 private:
  std::unordered_map<std::string, Value> globals_;
};

// str() of the result, or "error: " and the message
std::string Result(const std::string& expression) {
  Globals globals;
  const EvaluationBudget budget;
  try {
    return ToStr(Evaluate(*ParseExpression(expression), globals));
  } catch (const EvalError& e) {
    return std::string("error: ") + e.what();
  }
}

std::string WithoutAddresses(const std::string& text) {
  static const std::regex kAddress("0x[0-9a-f]+");
  return std::regex_replace(text, kAddress, "0x");
}

struct Row {
  const char* expression;
  const char* python;  // what Python prints
};

void ExpectPython(const std::vector<Row>& rows) {
  for (const Row& row : rows) {
    EXPECT_EQ(WithoutAddresses(Result(row.expression)), WithoutAddresses(row.python)) << row.expression;
  }
}

// the names of xacro's create_global_symbols, in its order
const std::vector<std::string> kDirect = {"list", "dict", "map", "len", "str", "float", "int",
                                          "True", "False", "min", "max", "round"};
const std::vector<std::string> kPythonOnly = {"abs", "all", "any", "complex", "divmod", "enumerate", "filter",
                                              "frozenset", "hash", "isinstance", "issubclass", "ord", "repr",
                                              "reversed", "slice", "set", "sum", "tuple", "type", "zip",
                                              "sorted", "range"};

TEST(PythonNamespace, HoldsExactlyXacrosNames) {
  Globals globals;
  const Value python = globals.Lookup("python");
  std::vector<std::string> names;
  for (const auto& [key, value] : python.dict->items) names.push_back(key.s);
  std::vector<std::string> expected = kDirect;
  expected.insert(expected.end(), kPythonOnly.begin(), kPythonOnly.end());
  EXPECT_EQ(names, expected);
}

TEST(PythonNamespace, OnlyXacrosDirectNamesAreGlobal) {
  Globals globals;
  for (const std::string& name : kDirect) EXPECT_TRUE(globals.all().count(name)) << name;
  // sorted and range are global too, with xacro's deprecation warning
  for (const std::string& name : kPythonOnly) {
    EXPECT_EQ(globals.all().count(name), name == "sorted" || name == "range" ? 1u : 0u) << name;
  }
  EXPECT_EQ(Result("sorted([2, 1]) + list(range(2))"), "[1, 2, 0, 1]");
  Globals warned;
  Evaluate(*ParseExpression("sorted([2, 1]) + list(range(2))"), warned);
  EXPECT_EQ(warned.warnings, (std::vector<std::string>{
                                 "Using sorted() directly is deprecated. Use python.sorted() instead.",
                                 "Using range() directly is deprecated. Use python.range() instead."}));
}

// Collections are built within the evaluation budget (evaluation_budget.h), whichever name builds
// them.
TEST(PythonNamespace, CollectionsStayWithinTheBudget) {
  const Row rows[] = {
      {"python.set(python.range(2000000))", "error: range() too large: 2000000 items (the limit is 1048576)"},
      {"python.frozenset(python.range(10**20))",
       "error: range() too large: 100000000000000000000 items (the limit is 1048576)"},
      {"list(python.zip(python.range(10**7), 'ab'))",
       "error: range() too large: 10000000 items (the limit is 1048576)"},
      {"python.sorted(python.reversed(python.range(10**9)))",
       "error: range() too large: 1000000000 items (the limit is 1048576)"},
      {"python.tuple(python.enumerate('a' * 2000000))",
       "error: string to iterate too large: 2000000 items (the limit is 1048576)"},
      {"python.set([list(python.range(1000000)) for i in python.range(5)][0])",
       "error: expressions make lists, tuples and dicts of more than 1048576 items in all (runaway comprehension?)"},
      {"len([python.set(python.range(1000000)) for i in python.range(5)])",
       "error: expressions build more than 4194304 list items in all (runaway comprehension or range()?)"},
      // a range is not built: its length, items and slices are computed
      {"len(python.range(10**18))", "1000000000000000000"},
      {"python.range(10**18)[-1]", "999999999999999999"},
      {"10**17 in python.range(0, 10**18, 7)", "False"},
  };
  for (const Row& row : rows) EXPECT_EQ(Result(row.expression), row.python) << row.expression;
}

TEST(PythonNamespace, List) {
  ExpectPython({
      {"python.list", "<class 'list'>"},
      {"python.list()", "[]"},
      {"python.list('ab')", "['a', 'b']"},
      {"python.list(python.range(3))", "[0, 1, 2]"},
      {"python.list(python.set([3, 1, 2]))", "[1, 2, 3]"},
      {"python.list(dict(a=1, b=2))", "['a', 'b']"},
      {"python.list(python.zip('ab', [1, 2]))", "[('a', 1), ('b', 2)]"},
      {"python.list(1)", "error: 'int' object is not iterable"},
      {"python.list(1, 2)", "error: list expected at most 1 argument, got 2"},
      {"python.list(x=1)", "error: list() takes no keyword arguments"},
      {"list is python.list", "True"},
  });
}

TEST(PythonNamespace, Dict) {
  ExpectPython({
      {"python.dict", "<class 'dict'>"},
      {"python.dict()", "{}"},
      {"python.dict(a=1, b=2)", "{'a': 1, 'b': 2}"},
      {"python.dict([('a', 1)], b=2)", "{'a': 1, 'b': 2}"},
      {"python.dict(python.zip('ab', python.range(2)))", "{'a': 0, 'b': 1}"},
      {"python.dict(python.enumerate('ab'))", "{0: 'a', 1: 'b'}"},
      {"python.dict(1)", "error: 'int' object is not iterable"},
      {"python.dict([1])", "error: cannot convert dictionary update sequence element #0 to a sequence"},
      {"python.dict([(1, 2, 3)])", "error: dictionary update sequence element #0 has length 3; 2 is required"},
      {"python.dict([([1], 2)])", "error: unhashable type: 'list'"},
      {"python.dict(1, 2)", "error: dict expected at most 1 argument, got 2"},
      {"{[1]: 2}", "error: unhashable type: 'list'"},
      {"dict(a=1)[[1]]", "error: unhashable type: 'list'"},
  });
}

TEST(PythonNamespace, Map) {
  ExpectPython({
      {"python.map", "<class 'map'>"},
      {"python.map(python.abs, [-1])", "<map object at 0x7efe6f92f6a0>"},
      {"list(python.map(python.abs, [-1, 2, -3]))", "[1, 2, 3]"},
      {"list(python.map(python.pow if 0 else pow, [2, 3], [2, 2, 2]))", "[4.0, 9.0]"},
      {"list(python.map(python.str.upper, ['a', 'b']))", "['A', 'B']"},
      {"python.map(python.abs)", "error: map() must have at least two arguments."},
      {"python.map(1, [1])", "<map object at 0x7efe6f92fb80>"},
      {"list(python.map(1, [1]))", "error: 'int' object is not callable"},
      {"python.map(python.abs, 1)", "error: 'int' object is not iterable"},
      {"python.map(python.abs, [1], x=1)", "error: map() takes no keyword arguments"},
      {"len(python.map(python.abs, [1]))", "error: object of type 'map' has no len()"},
      {"python.map(python.abs, [1])[0]", "error: 'map' object is not subscriptable"},
  });
}

TEST(PythonNamespace, Len) {
  ExpectPython({
      {"python.len", "<built-in function len>"},
      {"python.len([1, 2])", "2"},
      {"python.len('é€')", "2"},
      {"python.len(dict(a=1))", "1"},
      {"python.len(python.set([1, 1, 2]))", "2"},
      {"python.len(python.range(0, 10, 3))", "4"},
      {"python.len(python.range(2**70))", "error: Python int too large to convert to C ssize_t"},
      {"python.len(python.zip())", "error: object of type 'zip' has no len()"},
      {"python.len(1)", "error: object of type 'int' has no len()"},
      {"python.len()", "error: len() takes exactly one argument (0 given)"},
      {"python.len([], [])", "error: len() takes exactly one argument (2 given)"},
  });
}

TEST(PythonNamespace, Str) {
  ExpectPython({
      {"python.str", "<class 'str'>"},
      {"python.str()", ""},
      {"python.str(1.5)", "1.5"},
      {"python.str(python.set(['x']))", "{'x'}"},
      {"python.str(python.frozenset())", "frozenset()"},
      {"python.str(python.range(1, 5, 2))", "range(1, 5, 2)"},
      {"python.str(python.slice(2))", "slice(None, 2, None)"},
      {"python.str(1 + 2j)", "(1+2j)"},
      {"python.str(python.int)", "<class 'int'>"},
      {"python.str(python.zip)", "<class 'zip'>"},
      {"python.str(1, 2)", "error: str() argument 'encoding' must be str, not int"},
      {"python.str('a', 'utf-8')", "error: decoding str is not supported"},
      {"python.str(foo=1)", "error: 'foo' is an invalid keyword argument for str()"},
  });
}

TEST(PythonNamespace, Float) {
  ExpectPython({
      {"python.float", "<class 'float'>"},
      {"python.float()", "0.0"},
      {"python.float('1.5')", "1.5"},
      {"python.float(' -inf ')", "-inf"},
      {"python.float(True)", "1.0"},
      {"python.float(1j)", "error: float() argument must be a string or a real number, not 'complex'"},
      {"python.float([])", "error: float() argument must be a string or a real number, not 'list'"},
      {"python.float('x')", "error: could not convert string to float: 'x'"},
      {"python.float(1, 2)", "error: float expected at most 1 argument, got 2"},
      {"python.float(x=1)", "error: float() takes no keyword arguments"},
  });
}

TEST(PythonNamespace, Int) {
  ExpectPython({
      {"python.int", "<class 'int'>"},
      {"python.int()", "0"},
      {"python.int('12')", "12"},
      {"python.int('ff', 16)", "255"},
      {"python.int(-2.9)", "-2"},
      {"python.int(1j)", "error: int() argument must be a string, a bytes-like object or a real number, not 'complex'"},
      {"python.int('x')", "error: invalid literal for int() with base 10: 'x'"},
      {"python.int(float('nan'))", "error: cannot convert float NaN to integer"},
      {"python.int(x=1)", "error: 'x' is an invalid keyword argument for int()"},
      {"python.int(1, 2, 3)", "error: int() takes at most 2 arguments (3 given)"},
  });
}

TEST(PythonNamespace, True) {
  ExpectPython({
      {"python.True", "error: invalid syntax (<expression>, line 1)"},
      {"True", "True"},
      {"python.True if 0 else 1", "error: invalid syntax (<expression>, line 1)"},
  });
}

TEST(PythonNamespace, False) {
  ExpectPython({
      {"python.False", "error: invalid syntax (<expression>, line 1)"},
      {"False", "False"},
  });
}

TEST(PythonNamespace, Min) {
  ExpectPython({
      {"python.min", "<built-in function min>"},
      {"python.min([3, 1, 2])", "1"},
      {"python.min(3, 1, 2)", "1"},
      {"python.min([], default=5)", "5"},
      {"python.min([-3, 2], key=python.abs)", "2"},
      {"python.min([1.0, 1])", "1.0"},
      {"python.min([float('nan'), 1])", "nan"},
      {"python.min([1, float('nan')])", "1"},
      {"python.min(python.range(5, 10))", "5"},
      {"python.min(python.set([3, 9, 1]))", "1"},
      {"python.min('hello')", "e"},
      {"python.min([])", "error: min() arg is an empty sequence"},
      {"python.min(1, 2, default=3)", "error: Cannot specify a default for min() with multiple positional arguments"},
      {"python.min()", "error: min expected at least 1 argument, got 0"},
      {"python.min([1, 'a'])", "error: '<' not supported between instances of 'str' and 'int'"},
      {"python.min(1)", "error: 'int' object is not iterable"},
      {"python.min([], foo=1)", "error: 'foo' is an invalid keyword argument for min()"},
      {"python.min([1j, 2j])", "error: '<' not supported between instances of 'complex' and 'complex'"},
  });
}

TEST(PythonNamespace, Max) {
  ExpectPython({
      {"python.max", "<built-in function max>"},
      {"python.max([1, 2], key=python.abs)", "2"},
      {"python.max([-3, 2], key=python.abs)", "-3"},
      {"python.max(1, 2, key=None)", "2"},
      {"python.max([1, 1.0])", "1"},
      {"python.max(python.map(len, ['a', 'bbb', 'cc']))", "3"},
      {"python.max(python.zip([1, 2], [3, 0]))", "(2, 0)"},
      {"python.max('abc')", "c"},
      {"python.max()", "error: max expected at least 1 argument, got 0"},
      {"python.max([])", "error: max() arg is an empty sequence"},
  });
}

TEST(PythonNamespace, Round) {
  ExpectPython({
      {"python.round", "<built-in function round>"},
      {"python.round(2.5)", "2"},
      {"python.round(3.5)", "4"},
      {"python.round(2.675, 2)", "2.67"},
      {"python.round(1234.5678, -2)", "1200.0"},
      {"python.round(15, -1)", "20"},
      {"python.round(number=2.5)", "2"},
      {"python.round(2.5, ndigits=0)", "2.0"},
      {"python.round(1j)", "error: type complex doesn't define __round__ method"},
      {"python.round('a')", "error: type str doesn't define __round__ method"},
      {"python.round()", "error: round() missing required argument 'number' (pos 1)"},
      {"python.round(1, 2, 3)", "error: round() takes at most 2 arguments (3 given)"},
  });
}

TEST(PythonNamespace, Abs) {
  ExpectPython({
      {"python.abs", "<built-in function abs>"},
      {"python.abs(-2)", "2"},
      {"python.abs(-2.5)", "2.5"},
      {"python.abs(-0.0)", "0.0"},
      {"python.abs(True)", "1"},
      {"python.abs(3 + 4j)", "5.0"},
      {"python.abs(1e308 + 1e308j)", "1.4142135623730951e+308"},
      {"python.abs('a')", "error: bad operand type for abs(): 'str'"},
      {"python.abs()", "error: abs() takes exactly one argument (0 given)"},
      {"python.abs(1, 2)", "error: abs() takes exactly one argument (2 given)"},
      {"python.abs(x=1)", "error: abs() takes no keyword arguments"},
  });
}

TEST(PythonNamespace, All) {
  ExpectPython({
      {"python.all", "<built-in function all>"},
      {"python.all([])", "True"},
      {"python.all([1, 0])", "False"},
      {"python.all('abc')", "True"},
      {"python.all(python.map(python.abs, [1, 0]))", "False"},
      {"python.all(x > 0 for x in [1, 2])", "True"},
      {"python.all(1)", "error: 'int' object is not iterable"},
      {"python.all()", "error: all() takes exactly one argument (0 given)"},
  });
}

TEST(PythonNamespace, Any) {
  ExpectPython({
      {"python.any", "<built-in function any>"},
      {"python.any([0, ''])", "False"},
      {"python.any([0, 3])", "True"},
      {"python.any('')", "False"},
      {"python.any(python.zip([], []))", "False"},
      {"python.any(python.set([0]))", "False"},
      {"python.any(1)", "error: 'int' object is not iterable"},
      {"python.any()", "error: any() takes exactly one argument (0 given)"},
  });
}

TEST(PythonNamespace, Complex) {
  ExpectPython({
      {"python.complex", "<class 'complex'>"},
      {"python.complex()", "0j"},
      {"python.complex(1)", "(1+0j)"},
      {"python.complex(1, 2)", "(1+2j)"},
      {"python.complex(1.5, -2)", "(1.5-2j)"},
      {"python.complex(-0.0, 1)", "(-0+1j)"},
      {"python.complex(0, -0.0)", "-0j"},
      {"python.complex(1e16, 1e16)", "(1e+16+1e+16j)"},
      {"python.complex(True)", "(1+0j)"},
      {"python.complex(2j)", "2j"},
      {"python.complex(1 + 2j, 3j)", "(-2+2j)"},
      {"python.complex(real=1, imag=2)", "(1+2j)"},
      {"python.complex(imag=2)", "2j"},
      {"python.complex('1+2j')", "(1+2j)"},
      {"python.complex(' ( 1+2j ) ')", "(1+2j)"},
      {"python.complex('j')", "1j"},
      {"python.complex('-j')", "-1j"},
      {"python.complex('1-j')", "(1-1j)"},
      {"python.complex('1e3j')", "1000j"},
      {"python.complex('+1.5e-3-2.5e+3J')", "(0.0015-2500j)"},
      {"python.complex('inf-infj')", "(inf-infj)"},
      {"python.complex('infinityj')", "infj"},
      {"python.complex('nan')", "(nan+0j)"},
      {"python.complex('1_0j')", "10j"},
      {"python.complex('(1)')", "(1+0j)"},
      {"python.complex(1, float('nan'))", "(1+nanj)"},
      {"python.complex('1 + 2j')", "error: complex() arg is a malformed string"},
      {"python.complex('1__0j')", "error: could not convert string to complex: '1__0j'"},
      {"python.complex('')", "error: complex() arg is a malformed string"},
      {"python.complex('1+')", "error: complex() arg is a malformed string"},
      {"python.complex('1j+2')", "error: complex() arg is a malformed string"},
      {"python.complex('1', 2)", "error: complex() can't take second arg if first is a string"},
      {"python.complex(1, '2')", "error: complex() second arg can't be a string"},
      {"python.complex([1])", "error: complex() first argument must be a string or a number, not 'list'"},
      {"python.complex(1, [2])", "error: complex() second argument must be a number, not 'list'"},
      {"python.complex(1, 2, 3)", "error: complex() takes at most 2 arguments (3 given)"},
      {"python.complex(foo=1)", "error: 'foo' is an invalid keyword argument for complex()"},
      {"1j", "1j"},
      {"2.5j", "2.5j"},
      {"1e3j", "1000j"},
      {"1_0j", "10j"},
      {"-1j", "(-0-1j)"},
      {"1j ** 2", "(-1+0j)"},
      {"(1 + 1j) ** 100", "(-1125899906842624+0j)"},
      {"(1 + 1j) ** 101", "(-1125899906842634.5-1125899906842629.5j)"},
      {"(1 + 1j) ** -3", "(-0.25-0.25j)"},
      {"0j ** 0", "(1+0j)"},
      {"2 ** 1j", "(0.7692389013639721+0.6389612763136348j)"},
      {"1j ** 1j", "(0.20787957635076193+0j)"},
      {"2 ** 0.5j", "(0.9405421046832438+0.3396771251026685j)"},
      {"(1 + 2j) ** (3 + 4j)", "(0.129009594074467+0.03392409290517014j)"},
      {"(1e300 + 1e300j) ** 2", "(nan+nanj)"},
      {"(-1) ** 0.5", "(6.123233995736766e-17+1j)"},
      {"(-8.0) ** (1 / 3)", "(1.0000000000000002+1.7320508075688772j)"},
      {"(-1.5) ** 2.5", "(8.436824361685386e-16+2.7556759606310752j)"},
      {"(2 + 3j) / (4 - 5j)", "(-0.17073170731707318+0.5365853658536587j)"},
      {"(1 + 2j) / 1e-320", "(inf+infj)"},
      {"(1e300 + 1e300j) / (1e-300 + 1e-300j)", "(inf+0j)"},
      {"1j * float('inf')", "(nan+infj)"},
      {"python.complex(float('inf'), 0) * 2", "(inf+nanj)"},
      {"(1 + 2j).real", "1.0"},
      {"(1 + 2j).imag", "2.0"},
      {"(1 + 2j).conjugate()", "(1-2j)"},
      {"1 + 0j == 1", "True"},
      {"[1j, 1 + 1j]", "[1j, (1+1j)]"},
      {"python.sum([1j, 2])", "(2+1j)"},
      {"1j / 0", "error: complex division by zero"},
      {"0j ** -1", "error: 0.0 to a negative or complex power"},
      {"0j ** 1j", "error: 0.0 to a negative or complex power"},
      {"(2 + 0j) ** 2000", "error: complex exponentiation"},
      {"1e200 ** 2", "error: (34, 'Numerical result out of range')"},
      {"1j < 1", "error: '<' not supported between instances of 'complex' and 'int'"},
      {"(1 + 2j) // 1", "error: unsupported operand type(s) for //: 'complex' and 'int'"},
      {"(1 + 2j) % 1", "error: unsupported operand type(s) for %: 'complex' and 'int'"},
      {"~1j", "error: bad operand type for unary ~: 'complex'"},
      {"sqrt(1j)", "error: must be real number, not complex"},
      {"1j + 'a'", "error: unsupported operand type(s) for +: 'complex' and 'str'"},
  });
}

TEST(PythonNamespace, Divmod) {
  ExpectPython({
      {"python.divmod", "<built-in function divmod>"},
      {"python.divmod(7, 2)", "(3, 1)"},
      {"python.divmod(-7, 2)", "(-4, 1)"},
      {"python.divmod(7, -2)", "(-4, -1)"},
      {"python.divmod(7.5, 2)", "(3.0, 1.5)"},
      {"python.divmod(7, 2.5)", "(2.0, 2.0)"},
      {"python.divmod(-7.5, 2)", "(-4.0, 0.5)"},
      {"python.divmod(True, 2)", "(0, 1)"},
      {"python.divmod(1.0, 0)", "error: float divmod()"},
      {"python.divmod(1, 0)", "error: integer division or modulo by zero"},
      {"python.divmod(1j, 1)", "error: unsupported operand type(s) for divmod(): 'complex' and 'int'"},
      {"python.divmod('a', 1)", "error: unsupported operand type(s) for divmod(): 'str' and 'int'"},
      {"python.divmod(1)", "error: divmod expected 2 arguments, got 1"},
      {"python.divmod(1, 2, 3)", "error: divmod expected 2 arguments, got 3"},
  });
}

TEST(PythonNamespace, Enumerate) {
  ExpectPython({
      {"python.enumerate", "<class 'enumerate'>"},
      {"python.enumerate('ab')", "<enumerate object at 0x7efe6f9164d0>"},
      {"list(python.enumerate('ab'))", "[(0, 'a'), (1, 'b')]"},
      {"list(python.enumerate('ab', 5))", "[(5, 'a'), (6, 'b')]"},
      {"list(python.enumerate('ab', start=-1))", "[(-1, 'a'), (0, 'b')]"},
      {"list(python.enumerate(iterable=[1], start=2))", "[(2, 1)]"},
      {"list(python.enumerate(python.zip('ab', 'cd')))", "[(0, ('a', 'c')), (1, ('b', 'd'))]"},
      {"dict(python.enumerate('xy'))", "{0: 'x', 1: 'y'}"},
      {"[i * c for i, c in python.enumerate('ab')]", "['', 'b']"},
      {"python.enumerate([1], 'a')", "error: 'str' object cannot be interpreted as an integer"},
      {"python.enumerate()", "error: enumerate() missing required argument 'iterable'"},
      {"python.enumerate(1)", "error: 'int' object is not iterable"},
      {"python.enumerate([1], 2, 3)", "error: enumerate() takes at most 2 arguments (3 given)"},
      {"python.enumerate([1], foo=1)", "error: 'foo' is an invalid keyword argument for enumerate()"},
  });
}

TEST(PythonNamespace, Filter) {
  ExpectPython({
      {"python.filter", "<class 'filter'>"},
      {"python.filter(None, [1])", "<filter object at 0x7efe6f92fa00>"},
      {"list(python.filter(None, [0, 1, '', 2]))", "[1, 2]"},
      {"list(python.filter(python.abs, [0, 1, -1]))", "[1, -1]"},
      {"list(python.filter(len, ['', 'a']))", "['a']"},
      {"[x for x in python.filter(None, [0, 1, 2])]", "[1, 2]"},
      {"python.filter(None)", "error: filter expected 2 arguments, got 1"},
      {"python.filter(1, [1])", "<filter object at 0x7efe6f92fa90>"},
      {"list(python.filter(1, [1]))", "error: 'int' object is not callable"},
      {"python.filter(None, 1)", "error: 'int' object is not iterable"},
      {"python.filter(None, [1], x=1)", "error: filter() takes no keyword arguments"},
  });
}

TEST(PythonNamespace, Frozenset) {
  ExpectPython({
      {"python.frozenset", "<class 'frozenset'>"},
      {"python.frozenset()", "frozenset()"},
      {"python.frozenset([1, 2, 3])", "frozenset({1, 2, 3})"},
      {"python.frozenset('abc')", "frozenset({'c', 'a', 'b'})"},
      {"python.frozenset([python.frozenset([1, 2])])", "frozenset({frozenset({1, 2})})"},
      {"python.frozenset([5, 13, 21, 29, 37, 45]) | python.frozenset([1, 9])", "frozenset({1, 29, 45, 37, 5, 21, 9, 13})"},
      {"python.frozenset([1]) | python.set([2])", "frozenset({1, 2})"},
      {"python.frozenset([3, 1]) == python.set([1, 3])", "True"},
      {"python.frozenset([1]).copy()", "frozenset({1})"},
      {"python.frozenset(python.range(50)).difference([2])", "frozenset({0, 1, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49})"},
      {"python.frozenset(python.range(40, 0, -3)).intersection(python.range(10))", "frozenset({1, 4, 7})"},
      {"python.frozenset(python.range(8)).union(python.range(100, 120))", "frozenset({0, 1, 2, 3, 4, 5, 6, 7, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119})"},
      {"python.frozenset([1, 2]).symmetric_difference([2, 3])", "frozenset({1, 3})"},
      {"python.frozenset([1]).issubset([1, 2])", "True"},
      {"python.frozenset([1]).isdisjoint(python.set([1]))", "False"},
      {"python.sorted(python.frozenset('hello'))", "['e', 'h', 'l', 'o']"},
      {"python.frozenset([1, [2]])", "error: unhashable type: 'list'"},
      {"python.frozenset([1]).add(2)", "error: 'frozenset' object has no attribute 'add'"},
      {"python.frozenset(1)", "error: 'int' object is not iterable"},
      {"python.frozenset([1], [2])", "error: frozenset expected at most 1 argument, got 2"},
  });
}

TEST(PythonNamespace, Hash) {
  ExpectPython({
      {"python.hash", "<built-in function hash>"},
      {"python.hash(1)", "1"},
      {"python.hash(-1)", "-2"},
      {"python.hash(2**61)", "1"},
      {"python.hash(2**64 + 5)", "13"},
      {"python.hash(-2**100)", "-549755813888"},
      {"python.hash(0.1)", "230584300921369408"},
      {"python.hash(1.5)", "1152921504606846977"},
      {"python.hash(-1.5)", "-1152921504606846977"},
      {"python.hash(1e300)", "1224995262755759164"},
      {"python.hash(1e-300)", "482449582752280463"},
      {"python.hash(-0.0)", "0"},
      {"python.hash(float('inf'))", "314159"},
      {"python.hash(float('-inf'))", "-314159"},
      {"python.hash(True)", "1"},
      {"python.hash('')", "0"},
      {"python.hash('a')", "4644417185603328019"},
      {"python.hash('hello world')", "-5642461784034726774"},
      {"python.hash('é')", "6047309291227476195"},
      {"python.hash('€uro')", "7542247858446192590"},
      {"python.hash('😀')", "-3536540696076613844"},
      {"python.hash((1, 2))", "-3550055125485641917"},
      {"python.hash(())", "5740354900026072187"},
      {"python.hash(('a', 1.5, (2, 3)))", "-854318505611649837"},
      {"python.hash(python.frozenset())", "133146708735736"},
      {"python.hash(python.frozenset([1, 2]))", "-1826646154956904602"},
      {"python.hash(python.frozenset('abc'))", "8636088911049444515"},
      {"python.hash(1j)", "1000003"},
      {"python.hash(1 + 2j)", "2000007"},
      {"python.hash(python.range(3))", "-8338477496398685190"},
      {"python.hash(python.range(0, 10, 3))", "-1816567394155750349"},
      {"python.hash([1])", "error: unhashable type: 'list'"},
      {"python.hash((1, [2]))", "error: unhashable type: 'list'"},
      {"python.hash(python.set())", "error: unhashable type: 'set'"},
      {"python.hash(dict())", "error: unhashable type: 'dict'"},
      {"python.hash(python.slice(1))", "error: unhashable type: 'slice'"},
      {"python.hash()", "error: hash() takes exactly one argument (0 given)"},
      {"python.hash(1, 2)", "error: hash() takes exactly one argument (2 given)"},
  });
}

TEST(PythonNamespace, Isinstance) {
  ExpectPython({
      {"python.isinstance", "<built-in function isinstance>"},
      {"python.isinstance(1, python.int)", "True"},
      {"python.isinstance(True, python.int)", "True"},
      {"python.isinstance(1, python.float)", "False"},
      {"python.isinstance(1, (python.float, python.int))", "True"},
      {"python.isinstance(1, (python.int, 5))", "True"},
      {"python.isinstance(1, ())", "False"},
      {"python.isinstance(1, ((python.str,), (python.int,)))", "True"},
      {"python.isinstance(None, python.int | None)", "True"},
      {"python.isinstance('a', python.int | python.float)", "False"},
      {"python.isinstance(python.zip(), python.zip)", "True"},
      {"python.isinstance(python.range(1), python.range)", "True"},
      {"python.isinstance(python.set(), python.frozenset)", "False"},
      {"python.isinstance(python.int, python.type)", "True"},
      {"python.isinstance(python.type('X', (), {})(), python.type)", "False"},
      {"python.isinstance(1, (python.str, 5))", "error: isinstance() arg 2 must be a type, a tuple of types, or a union"},
      {"python.isinstance(1, 5)", "error: isinstance() arg 2 must be a type, a tuple of types, or a union"},
      {"python.isinstance(1)", "error: isinstance expected 2 arguments, got 1"},
      {"python.isinstance(1, python.int, 3)", "error: isinstance expected 2 arguments, got 3"},
  });
}

TEST(PythonNamespace, Issubclass) {
  ExpectPython({
      {"python.issubclass", "<built-in function issubclass>"},
      {"python.issubclass(python.type(True), python.int)", "True"},
      {"python.issubclass(python.int, python.type(True))", "False"},
      {"python.issubclass(python.int, (python.float, python.int))", "True"},
      {"python.issubclass(python.int, python.int | python.str)", "True"},
      {"python.issubclass(python.int, ())", "False"},
      {"python.issubclass(python.type(python.set()), python.frozenset)", "False"},
      {"python.issubclass(1, ())", "False"},
      {"python.issubclass(1, python.int)", "error: issubclass() arg 1 must be a class"},
      {"python.issubclass(python.int, 1)", "error: issubclass() arg 2 must be a class, a tuple of classes, or a union"},
      {"python.issubclass(1, 1)", "error: issubclass() arg 1 must be a class"},
      {"python.issubclass(python.int)", "error: issubclass expected 2 arguments, got 1"},
  });
}

TEST(PythonNamespace, Ord) {
  ExpectPython({
      {"python.ord", "<built-in function ord>"},
      {"python.ord('a')", "97"},
      {"python.ord('é')", "233"},
      {"python.ord('€')", "8364"},
      {"python.ord('😀')", "128512"},
      {"python.ord('ab')", "error: ord() expected a character, but string of length 2 found"},
      {"python.ord('')", "error: ord() expected a character, but string of length 0 found"},
      {"python.ord(1)", "error: ord() expected string of length 1, but int found"},
      {"python.ord()", "error: ord() takes exactly one argument (0 given)"},
  });
}

TEST(PythonNamespace, Repr) {
  ExpectPython({
      {"python.repr", "<built-in function repr>"},
      {"python.repr('a')", "'a'"},
      {"python.repr(\"it's\")", "\"it's\""},
      {"python.repr([1, 'a'])", "[1, 'a']"},
      {"python.repr(None)", "None"},
      {"python.repr(python.set(['x']))", "{'x'}"},
      {"python.repr(1 - 1j)", "(1-1j)"},
      {"python.repr(python.str.upper)", "<method 'upper' of 'str' objects>"},
      {"python.repr(python.slice(1, 'a'))", "slice(1, 'a', None)"},
      {"python.repr()", "error: repr() takes exactly one argument (0 given)"},
  });
}

TEST(PythonNamespace, Reversed) {
  ExpectPython({
      {"python.reversed", "<class 'reversed'>"},
      {"python.reversed([1])", "<list_reverseiterator object at 0x7efe6f92f850>"},
      {"python.reversed('ab')", "<reversed object at 0x7efe6f92fa30>"},
      {"python.reversed((1,))", "<reversed object at 0x7efe6f92ffd0>"},
      {"python.reversed(dict(a=1))", "<dict_reversekeyiterator object at 0x7efe6f916480>"},
      {"python.reversed(python.range(3))", "<range_iterator object at 0x7efe6f92f7b0>"},
      {"list(python.reversed([1, 2, 3]))", "[3, 2, 1]"},
      {"list(python.reversed('abc'))", "['c', 'b', 'a']"},
      {"list(python.reversed(dict(a=1, b=2)))", "['b', 'a']"},
      {"list(python.reversed(python.range(1, 10, 3)))", "[7, 4, 1]"},
      {"python.reversed(python.set([1]))", "error: 'set' object is not reversible"},
      {"python.reversed(5)", "error: 'int' object is not reversible"},
      {"python.reversed(python.zip())", "error: 'zip' object is not reversible"},
      {"python.reversed()", "error: reversed expected 1 argument, got 0"},
  });
}

TEST(PythonNamespace, Slice) {
  ExpectPython({
      {"python.slice", "<class 'slice'>"},
      {"python.slice(1, 2)", "slice(1, 2, None)"},
      {"python.slice(1)", "slice(None, 1, None)"},
      {"python.slice('a')", "slice(None, 'a', None)"},
      {"python.slice(1, 2, 3).indices(10)", "(1, 2, 3)"},
      {"python.slice(None, None, -1).indices(5)", "(4, -1, -1)"},
      {"python.slice(-100, 100).indices(5)", "(0, 5, 1)"},
      {"python.slice(1, 2) == python.slice(1, 2)", "True"},
      {"python.slice(1, 2) < python.slice(1, 3)", "True"},
      {"python.slice(1, 2, 3).start", "1"},
      {"python.slice(1, 2, 3).stop", "2"},
      {"python.slice(1, 2, 3).step", "3"},
      {"[1, 2, 3, 4, 5][python.slice(1, None, 2)]", "[2, 4]"},
      {"'abcdef'[python.slice(None, None, -2)]", "fdb"},
      {"(1, 2, 3)[python.slice(2)]", "(1, 2)"},
      {"python.range(10)[python.slice(3, None)]", "range(3, 10)"},
      {"[1, 2, 3][:10**30]", "[1, 2, 3]"},
      {"python.slice(1, 2).indices(-1)", "error: length should not be negative"},
      {"[1, 2, 3][python.slice('a', None)]", "error: slice indices must be integers or None or have an __index__ method"},
      {"[1, 2, 3]['a':]", "error: slice indices must be integers or None or have an __index__ method"},
      {"dict(a=1)[1:2]", "error: unhashable type: 'slice'"},
      {"python.slice()", "error: slice expected at least 1 argument, got 0"},
      {"python.slice(1, 2, 3, 4)", "error: slice expected at most 3 arguments, got 4"},
  });
}

TEST(PythonNamespace, Set) {
  ExpectPython({
      {"python.set", "<class 'set'>"},
      {"python.set()", "set()"},
      {"python.set([1, 2])", "{1, 2}"},
      {"python.set([3, 1, 2])", "{1, 2, 3}"},
      {"python.set([8, 1])", "{8, 1}"},
      {"python.set([8, 16, 0, 24])", "{8, 16, 0, 24}"},
      {"python.set([-1, -2, -3])", "{-3, -1, -2}"},
      {"python.set([0.5, 1.5, 2.5])", "{0.5, 1.5, 2.5}"},
      {"python.set([(1, 2), (3, 4)])", "{(1, 2), (3, 4)}"},
      {"python.set([True, 1, 1.0])", "{True}"},
      {"python.set([0.0, -0.0, 0])", "{0.0}"},
      {"python.set([1j, 2j, 1 + 0j, 1])", "{(1+0j), 1j, 2j}"},
      {"python.set([2**64, 2**65, 2**66, 3])", "{18446744073709551616, 36893488147419103232, 73786976294838206464, 3}"},
      {"python.set(python.range(0, 200, 9))", "{0, 135, 9, 144, 18, 153, 27, 162, 36, 171, 45, 180, 54, 189, 63, 198, 72, 81, 90, 99, 108, 117, 126}"},
      {"python.set(python.range(100, 0, -7))", "{65, 2, 100, 37, 72, 9, 44, 79, 16, 51, 86, 23, 58, 93, 30}"},
      {"python.set([33, 1, 65, 97, 129])", "{65, 33, 129, 1, 97}"},
      {"python.set('abcdef')", "{'d', 'f', 'b', 'c', 'a', 'e'}"},
      {"python.set(['base', 'shoulder', 'elbow', 'wrist'])", "{'wrist', 'shoulder', 'base', 'elbow'}"},
      {"python.set(dict(a=1, b=2))", "{'a', 'b'}"},
      {"python.set(python.map(python.abs, [-1, 1, 2]))", "{1, 2}"},
      {"python.set([1, 2]) | python.set([3])", "{1, 2, 3}"},
      {"python.set([2]) | python.frozenset([1])", "{1, 2}"},
      {"python.set([1, 2]) & python.set([2, 3])", "{2}"},
      {"python.set([1, 2]) - python.set([2])", "{1}"},
      {"python.set([1, 2]) ^ python.set([2, 3])", "{1, 3}"},
      {"python.set(python.range(50)) - python.set(python.range(0, 50, 2))", "{1, 3, 5, 7, 9, 11, 13, 15, 17, 19, 21, 23, 25, 27, 29, 31, 33, 35, 37, 39, 41, 43, 45, 47, 49}"},
      {"python.set(python.range(50)) ^ python.set(python.range(25, 75))", "{0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74}"},
      {"python.set(python.range(50)) & python.set(python.range(25, 75, 3))", "{34, 37, 40, 43, 46, 49, 25, 28, 31}"},
      {"python.set([1]) < python.set([1, 2])", "True"},
      {"python.set([1, 2]) < python.set([1, 2])", "False"},
      {"python.set([1, 2]) <= python.set([1, 2])", "True"},
      {"python.set([1, 2]) >= python.set([3])", "False"},
      {"python.set([1]) == python.frozenset([1])", "True"},
      {"python.set([1]).union([2], [3])", "{1, 2, 3}"},
      {"python.set([1, 2, 3]).intersection([2, 3], [3])", "{3}"},
      {"python.set([1, 2]).difference([2], [1])", "set()"},
      {"python.set([1, 2]).issuperset([1])", "True"},
      {"python.set([1]).add(2)", "None"},
      {"python.set([1]).discard(2)", "None"},
      {"[s for s in [python.set([1, 9, 17])] if s.discard(9) is None if s.add(25) is None][0]", "{1, 25, 17}"},
      {"[[s.pop() for i in python.range(3)] for s in [python.set([40, 3, 11, 8])]][0]", "[40, 11, 3]"},
      {"[s for s in [python.set(python.range(20))] if s.difference_update(python.range(15)) is None][0]", "{15, 16, 17, 18, 19}"},
      {"[s for s in [python.set([1, 2, 3])] if s.intersection_update([3, 2, 7]) is None][0]", "{2, 3}"},
      {"[s for s in [python.set([1, 2])] if s.symmetric_difference_update([2, 5]) is None][0]", "{1, 5}"},
      {"[s for s in [python.set([1])] if s.update([3], 'a') is None][0]", "{'a', 1, 3}"},
      {"[s for s in [python.set([1])] if s.clear() is None][0]", "set()"},
      {"1 in python.set([1.0])", "True"},
      {"python.set([1]) in python.set([python.frozenset([1])])", "True"},
      {"python.sum(python.set([1, 2, 3]))", "6"},
      {"len(python.set(python.range(100000)))", "100000"},
      {"python.set([[1]])", "error: unhashable type: 'list'"},
      {"[1] in python.set([1])", "error: unhashable type: 'list'"},
      {"python.set().pop()", "error: 'pop from an empty set'"},
      {"python.set([1]).remove(2)", "error: 2"},
      {"python.set([1]) | [2]", "error: unsupported operand type(s) for |: 'set' and 'list'"},
      {"python.set([1]) <= [1]", "error: '<=' not supported between instances of 'set' and 'list'"},
      {"python.set() < 1", "error: '<' not supported between instances of 'set' and 'int'"},
      {"python.set([1], [2])", "error: set expected at most 1 argument, got 2"},
      {"python.set(a=1)", "error: set() takes no keyword arguments"},
      {"python.set(1)", "error: 'int' object is not iterable"},
  });
}

TEST(PythonNamespace, Sum) {
  ExpectPython({
      {"python.sum", "<built-in function sum>"},
      {"python.sum([1, 2, 3])", "6"},
      {"python.sum([1.5, 2])", "3.5"},
      {"python.sum([0.1] * 10)", "0.9999999999999999"},
      {"python.sum([1e100, 1.0, -1e100])", "0.0"},
      {"python.sum(python.range(10), 0.5)", "45.5"},
      {"python.sum([[1], [2]], [])", "[1, 2]"},
      {"python.sum([(1,), (2,)], ())", "(1, 2)"},
      {"python.sum([1, 2], start=10)", "13"},
      {"python.sum([1, 2], 10)", "13"},
      {"python.sum(python.map(python.abs, python.range(-3, 3)))", "9"},
      {"python.sum(['a'], '')", "error: sum() can't sum strings [use ''.join(seq) instead]"},
      {"python.sum(['a', 'b'])", "error: unsupported operand type(s) for +: 'int' and 'str'"},
      {"python.sum()", "error: sum() takes at least 1 positional argument (0 given)"},
      {"python.sum([1], 2, 3)", "error: sum() takes at most 2 arguments (3 given)"},
      {"python.sum([1], foo=2)", "error: 'foo' is an invalid keyword argument for sum()"},
      {"python.sum(1)", "error: 'int' object is not iterable"},
  });
}

TEST(PythonNamespace, Tuple) {
  ExpectPython({
      {"python.tuple", "<class 'tuple'>"},
      {"python.tuple()", "()"},
      {"python.tuple('ab')", "('a', 'b')"},
      {"python.tuple(python.range(3))", "(0, 1, 2)"},
      {"python.tuple(python.map(python.abs, [-1, -2]))", "(1, 2)"},
      {"python.tuple([1])", "(1,)"},
      {"tuple([1])", "error: name 'tuple' is not defined"},
      {"python.tuple(1)", "error: 'int' object is not iterable"},
      {"python.tuple(1, 2)", "error: tuple expected at most 1 argument, got 2"},
  });
}

TEST(PythonNamespace, Type) {
  ExpectPython({
      {"python.type", "<class 'type'>"},
      {"python.type(1)", "<class 'int'>"},
      {"python.type('a')", "<class 'str'>"},
      {"python.type(None)", "<class 'NoneType'>"},
      {"python.type(True)", "<class 'bool'>"},
      {"python.type(1j)", "<class 'complex'>"},
      {"python.type(python.set())", "<class 'set'>"},
      {"python.type(python.frozenset())", "<class 'frozenset'>"},
      {"python.type(python.range(1))", "<class 'range'>"},
      {"python.type(python.slice(1))", "<class 'slice'>"},
      {"python.type(python.zip())", "<class 'zip'>"},
      {"python.type(python.map(str, []))", "<class 'map'>"},
      {"python.type(python.filter(None, []))", "<class 'filter'>"},
      {"python.type(python.enumerate([]))", "<class 'enumerate'>"},
      {"python.type(python.reversed([]))", "<class 'list_reverseiterator'>"},
      {"python.type(python.reversed(()))", "<class 'reversed'>"},
      {"python.type(python.reversed(python.range(2)))", "<class 'range_iterator'>"},
      {"python.type(python.reversed(dict()))", "<class 'dict_reversekeyiterator'>"},
      {"python.type(python.len)", "<class 'builtin_function_or_method'>"},
      {"python.type(python.int)", "<class 'type'>"},
      {"python.type(python.type)", "<class 'type'>"},
      {"python.type(python.int | None)", "<class 'types.UnionType'>"},
      {"python.type(1) is python.int", "True"},
      {"python.type(None)()", "None"},
      {"python.type(True)('x')", "True"},
      {"python.type('X', (), {})", "<class 'X'>"},
      {"python.type('X', (), {'a': 1}).a", "1"},
      {"python.type('X', (), {'a': 1})().a", "1"},
      {"python.type(python.type('X', (), {})())", "<class 'X'>"},
      {"python.type('X', (python.type('Y', (), {'b': 2}),), {'a': 1})().b", "2"},
      {"python.int | python.float", "int | float"},
      {"python.int | None", "int | None"},
      {"None | python.int", "None | int"},
      {"python.int | python.int", "<class 'int'>"},
      {"python.int | python.float == python.float | python.int", "True"},
      {"python.str.upper('a')", "A"},
      {"python.str.join(',', ['a', 'b'])", "a,b"},
      {"python.list.count([1, 1], 1)", "2"},
      {"python.set.union(python.set([1]), [2])", "{1, 2}"},
      {"python.str.upper", "<method 'upper' of 'str' objects>"},
      {"python.type('X', (), {'a': 1})().b", "error: 'X' object has no attribute 'b'"},
      {"python.type('X', (), {}).b", "error: type object 'X' has no attribute 'b'"},
      {"python.type('X', (), {})(1)", "error: X() takes no arguments"},
      {"python.type(1, (), {})", "error: type.__new__() argument 1 must be str, not int"},
      {"python.type('X', [], {})", "error: type.__new__() argument 2 must be tuple, not list"},
      {"python.type('X', (1,), {})", "error: metaclass conflict: the metaclass of a derived class must be a (non-strict) subclass of the metaclasses of all its bases"},
      {"python.type('X', (), 1)", "error: type.__new__() argument 3 must be dict, not int"},
      {"python.type('X', ())", "error: type() takes 1 or 3 arguments"},
      {"python.type()", "error: type() takes 1 or 3 arguments"},
      {"python.type(1, a=2)", "error: type() takes no keyword arguments"},
      {"python.type(None)(1)", "error: NoneType takes no arguments"},
      {"python.type(python.len)()", "error: cannot create 'builtin_function_or_method' instances"},
      {"python.type(python.int | None)()", "error: cannot create 'types.UnionType' instances"},
      {"python.type(python.zip())()", "<zip object at 0x7efe6f92bfc0>"},
      {"python.int | 1", "error: unsupported operand type(s) for |: 'type' and 'int'"},
      {"python.str.upper(1)", "error: descriptor 'upper' for 'str' objects doesn't apply to a 'int' object"},
      {"python.str.upper()", "error: unbound method str.upper() needs an argument"},
      {"python.str.nosuch", "error: type object 'str' has no attribute 'nosuch'"},
  });
}

TEST(PythonNamespace, Zip) {
  ExpectPython({
      {"python.zip", "<class 'zip'>"},
      {"python.zip([1, 2], 'ab')", "<zip object at 0x7efe6f92bfc0>"},
      {"list(python.zip([1, 2], 'ab'))", "[(1, 'a'), (2, 'b')]"},
      {"list(python.zip())", "[]"},
      {"list(python.zip([1, 2], [3, 4], strict=True))", "[(1, 3), (2, 4)]"},
      {"dict(python.zip(['a', 'b'], [1, 2]))", "{'a': 1, 'b': 2}"},
      {"[a + b for a, b in python.zip([1, 2], [10, 20])]", "[11, 22]"},
      {"(1, 2) in python.zip([1], [2])", "True"},
      {"python.sorted(python.zip([2, 1], 'ab'))", "[(1, 'b'), (2, 'a')]"},
      {"list(python.zip([1], [2, 3], strict=True))", "error: zip() argument 2 is longer than argument 1"},
      {"list(python.zip([1, 2], [2], [3], strict=True))", "error: zip() argument 2 is shorter than argument 1"},
      {"list(python.zip([1], [2], [3, 4], strict=True))", "error: zip() argument 3 is longer than arguments 1-2"},
      {"python.zip(foo=1)", "error: 'foo' is an invalid keyword argument for zip()"},
      {"python.zip(1)", "error: 'int' object is not iterable"},
      {"python.zip()[0]", "error: 'zip' object is not subscriptable"},
  });
}

TEST(PythonNamespace, Sorted) {
  ExpectPython({
      {"python.sorted", "<built-in function sorted>"},
      {"sorted([3, 1, 2])", "[1, 2, 3]"},
      {"python.sorted([3, 1, 2])", "[1, 2, 3]"},
      {"python.sorted([3, 1, 2], reverse=True)", "[3, 2, 1]"},
      {"python.sorted(['b', 'A', 'a'])", "['A', 'a', 'b']"},
      {"python.sorted(['bb', 'a', 'ccc'], key=len)", "['a', 'bb', 'ccc']"},
      {"python.sorted(['bb', 'a', 'ccc'], key=len, reverse=True)", "['ccc', 'bb', 'a']"},
      {"python.sorted([1, 1.0, True], reverse=True)", "[1, 1.0, True]"},
      {"python.sorted([1.0, 1, True])", "[1.0, 1, True]"},
      {"python.sorted([3, float('nan'), 1])", "[3, nan, 1]"},
      {"python.sorted([float('nan'), 3, 1, 2])", "[nan, 1, 2, 3]"},
      {"python.sorted([2, 1, float('nan'), 0, -1])", "[-1, 0, 1, 2, nan]"},
      {"python.sorted([python.set([3]), python.set([1]), python.set([1, 2]), python.set([2])])", "[{3}, {1}, {2}, {1, 2}]"},
      {"python.sorted([-3, 2, -1], key=python.abs)", "[-1, 2, -3]"},
      {"python.sorted('hello')", "['e', 'h', 'l', 'l', 'o']"},
      {"python.sorted(dict(b=1, a=2))", "['a', 'b']"},
      {"python.sorted(python.range(60, 0, -1))[:5]", "[1, 2, 3, 4, 5]"},
      {"python.sorted([x % 7 for x in python.range(100)])[40:50]", "[2, 2, 2, 2, 3, 3, 3, 3, 3, 3]"},
      {"python.sorted([1], foo=1)", "error: 'foo' is an invalid keyword argument for sort()"},
      {"python.sorted([1], key=1)", "error: 'int' object is not callable"},
      {"python.sorted([2, 1], None)", "error: sorted expected 1 argument, got 2"},
      {"python.sorted()", "error: sorted expected 1 argument, got 0"},
      {"python.sorted(1)", "error: 'int' object is not iterable"},
      {"python.sorted([1, 'a'])", "error: '<' not supported between instances of 'str' and 'int'"},
  });
}

TEST(PythonNamespace, Range) {
  ExpectPython({
      {"python.range", "<class 'range'>"},
      {"range(3)", "range(0, 3)"},
      {"python.range(3)", "range(0, 3)"},
      {"python.range(1, 10, 2)", "range(1, 10, 2)"},
      {"python.range(10, 0, -3)", "range(10, 0, -3)"},
      {"python.range(True)", "range(0, 1)"},
      {"python.range(0, 10)[::-1]", "range(9, -1, -1)"},
      {"python.range(10)[2:8:3]", "range(2, 8, 3)"},
      {"python.range(10)[2:9:3]", "range(2, 9, 3)"},
      {"python.range(0, 10, 3)[-100:100]", "range(0, 12, 3)"},
      {"python.range(1, 10, 2)[-1]", "9"},
      {"python.range(10**30)[5]", "5"},
      {"python.range(3) == python.range(0, 3, 1)", "True"},
      {"python.range(0) == python.range(5, 2)", "True"},
      {"python.range(1, 2, 5) == python.range(1, 3, 7)", "True"},
      {"len(python.range(10, 0, -3))", "4"},
      {"1.0 in python.range(3)", "True"},
      {"5 in python.range(0, 10, 2)", "False"},
      {"-3 in python.range(0, -10, -3)", "True"},
      {"python.range(3).index(2)", "2"},
      {"python.range(3).count(1)", "1"},
      {"python.range(1, 2, 3).step", "3"},
      {"list(python.range(5))", "[0, 1, 2, 3, 4]"},
      {"python.sum(python.range(101))", "5050"},
      {"[x for x in python.range(3)]", "[0, 1, 2]"},
      {"python.range(5)[10]", "error: range object index out of range"},
      {"python.range(3).index(5)", "error: 5 is not in range"},
      {"python.range()", "error: range expected at least 1 argument, got 0"},
      {"python.range(1, 2, 3, 4)", "error: range expected at most 3 arguments, got 4"},
      {"python.range(1.5)", "error: 'float' object cannot be interpreted as an integer"},
      {"python.range(1, 2, 0)", "error: range() arg 3 must not be zero"},
      {"python.range(3) + python.range(3)", "error: unsupported operand type(s) for +: 'range' and 'range'"},
      {"python.range(3)['a']", "error: range indices must be integers or slices, not str"},
      {"python.range(3)[::0]", "error: slice step cannot be zero"},
      {"len(python.range(2**70))", "error: Python int too large to convert to C ssize_t"},
  });
}

// xacro exposes all of math, directly and as math.*: the functions Python 3.8 to 3.11 added too
TEST(PythonNamespace, MathFunctionsSincePython38) {
  ExpectPython({
      {"math.comb(5,2)", "10"},
      {"math.comb(50,25)", "126410606437752"},
      {"math.comb(5,7)", "0"},
      {"math.comb(-1,2)", "error: n must be a non-negative integer"},
      {"math.comb(5,-1)", "error: k must be a non-negative integer"},
      {"math.comb(1.5,1)", "error: 'float' object cannot be interpreted as an integer"},
      {"math.comb(5)", "error: comb expected 2 arguments, got 1"},
      {"math.comb(True, False)", "1"},
      {"math.comb(120, 60)", "96614908840363322603893139521372656"},
      {"math.perm(5,2)", "20"},
      {"math.perm(5)", "120"},
      {"math.perm(5,7)", "0"},
      {"math.perm(-1)", "error: factorial() not defined for negative values"},
      {"math.perm(30)", "265252859812191058636308480000000"},
      {"math.dist([0,0],[3,4])", "5.0"},
      {"math.dist([0],[1,2])", "error: both points must have the same number of dimensions"},
      {"math.dist(1,2)", "error: 'int' object is not iterable"},
      {"math.dist((1,2),(3,'a'))", "error: must be real number, not str"},
      {"math.dist((1,2,3),(4,5,6))", "5.196152422706632"},
      {"math.dist([0.1, 0.2, 0.3], [1, 2, 3])", "3.3674916480965473"},
      {"math.frexp(8.0)", "(0.5, 4)"},
      {"math.frexp(0)", "(0.0, 0)"},
      {"math.frexp(float('inf'))", "(inf, 0)"},
      {"math.frexp(-0.0)", "(-0.0, 0)"},
      {"math.frexp(0.1)", "(0.8, -3)"},
      {"math.lcm(4,6)", "12"},
      {"math.lcm()", "1"},
      {"math.lcm(0,5)", "0"},
      {"math.lcm(-4,6)", "12"},
      {"math.lcm(1.5)", "error: 'float' object cannot be interpreted as an integer"},
      {"math.lcm(4, 6, 10)", "60"},
      {"math.nextafter(1,2)", "1.0000000000000002"},
      {"math.nextafter(1)", "error: nextafter expected 2 arguments, got 1"},
      {"math.nextafter(0, -1)", "-5e-324"},
      {"math.prod([1,2,3])", "6"},
      {"math.prod([])", "1"},
      {"math.prod([1.5,2])", "3.0"},
      {"math.prod([2,3],start=2)", "12"},
      {"math.prod('ab')", "error: can't multiply sequence by non-int of type 'str'"},
      {"math.prod(['a', 2])", "aa"},
      {"math.prod([1],[2])", "error: prod() takes exactly 1 positional argument (2 given)"},
      {"math.ulp(1.0)", "2.220446049250313e-16"},
      {"math.ulp(0)", "5e-324"},
      {"math.ulp(float('inf'))", "inf"},
      {"math.ulp(float('nan'))", "nan"},
      {"math.ulp(-2.0)", "4.440892098500626e-16"},
      {"math.ulp(1e308)", "1.99584030953472e+292"},
      {"math.hypot(1,2,2)", "3.0"},
      {"math.hypot()", "0.0"},
      {"math.hypot(3)", "3.0"},
      {"math.hypot(3, 4)", "5.0"},
      {"math.hypot(1, 1)", "1.4142135623730951"},
      {"math.hypot(0.1, 0.2, 0.3)", "0.3741657386773941"},
      {"math.hypot(1e308, 1e308, 1e308)", "1.7320508075688772e+308"},
      {"math.hypot(1, 2, 3, 4, 5, 6, 7)", "11.832159566199232"},
      {"math.hypot(float('nan'), float('inf'))", "inf"},
      {"math.gcd()", "0"},
      {"math.gcd(1.5)", "error: 'float' object cannot be interpreted as an integer"},
      {"math.factorial(1.5)", "error: 'float' object cannot be interpreted as an integer"},
      {"math.isqrt('a')", "error: 'str' object cannot be interpreted as an integer"},
      {"comb(5, 2)", "10"},
      {"prod([2, 2])", "4"},
  });
}

}  // namespace
}  // namespace urdfsnap::xacro
