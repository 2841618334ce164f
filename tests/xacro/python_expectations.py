#!/usr/bin/env python3
"""Prints the expected rows of python_namespace_test.cpp: what Python itself makes of each
expression, evaluated with the globals xacro gives its expressions (create_global_symbols in
xacro/__init__.py: a few builtins directly, all of them under `python`, math, no other builtins).

usage: PYTHONHASHSEED=0 python3 tests/xacro/python_expectations.py < cases.txt
       PYTHONHASHSEED=0 python3 tests/xacro/python_expectations.py --check tests/xacro/python_namespace_test.cpp

Input: expressions, one per line; a line `## Name` starts the test of that name. Output: the C++
TEST blocks, each row {"expression", "str(result)"} or {"expression", "error: message"}. With
--check it re-evaluates the rows of the test file instead and prints those Python disagrees with.
Run it with Python 3.11 (xacro's reference) and PYTHONHASHSEED=0 (string hashes, hence the
order of sets of strings, depend on it).
"""
import builtins
import math
import re
import sys
import types

DIRECT = ['list', 'dict', 'map', 'len', 'str', 'float', 'int', 'True', 'False', 'min', 'max', 'round']
PYTHON = DIRECT + ['abs', 'all', 'any', 'complex', 'divmod', 'enumerate', 'filter', 'frozenset', 'hash',
                   'isinstance', 'issubclass', 'ord', 'repr', 'reversed', 'slice', 'set', 'sum', 'tuple',
                   'type', 'zip', 'sorted', 'range']


def xacro_globals():
    g = {k: getattr(builtins, k) for k in DIRECT + ['sorted', 'range']}
    g['python'] = types.SimpleNamespace(**{k: getattr(builtins, k) for k in PYTHON})
    math_names = {k: v for k, v in math.__dict__.items() if not k.startswith('_')}
    g.update(math_names)
    g['math'] = types.SimpleNamespace(**math_names)
    g['__builtins__'] = {}
    return g


def quote(text):
    return '"' + text.replace('\\', '\\\\').replace('"', '\\"') + '"'


def python_result(expression):
    try:
        return str(eval(compile(expression, '<expression>', 'eval'), xacro_globals()))
    except Exception as e:  # the message Python raises is the expectation
        return 'error: ' + str(e)


def check(path):
    row = re.compile(r'^\s*\{"((?:[^"\\]|\\.)*)", "((?:[^"\\]|\\.)*)"\},$')
    unescape = lambda t: t.replace('\\"', '"').replace('\\\\', '\\')
    address = re.compile(r'0x[0-9a-f]+')
    rows = bad = 0
    inside = False  # only the rows of ExpectPython({...}) are Python's; the others are urdfsnap's limits
    for line in open(path, encoding='utf-8'):
        if 'ExpectPython({' in line or line.strip() == '});':
            inside = 'ExpectPython({' in line
            continue
        m = row.match(line)
        if not inside or not m:
            continue
        rows += 1
        expression, expected = unescape(m.group(1)), unescape(m.group(2))
        got = python_result(expression)
        if address.sub('0x', got) != address.sub('0x', expected):
            bad += 1
            print('%s\n  file:   %s\n  python: %s' % (expression, expected[:200], got[:200]))
    print('%d rows, %d differ' % (rows, bad))
    return 1 if bad else 0


def main():
    open_test = False
    for line in sys.stdin:
        line = line.rstrip('\n')
        if not line.strip():
            continue
        if line.startswith('## '):
            if open_test:
                print('  });\n}\n')
            print('TEST(PythonNamespace, %s) {\n  ExpectPython({' % line[3:])
            open_test = True
            continue
        print('      {%s, %s},' % (quote(line), quote(python_result(line))))
    if open_test:
        print('  });\n}')


if __name__ == '__main__':
    if len(sys.argv) == 3 and sys.argv[1] == '--check':
        sys.exit(check(sys.argv[2]))
    main()
