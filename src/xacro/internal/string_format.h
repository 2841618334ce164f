// Python's printf-style string formatting: `'%s_%d' % (name, 3)`, `'%.3f' % x`, `'%(k)s' % d`.
#pragma once

#include <string>

#include "xacro/internal/python_value.h"

namespace urdfsnap::xacro {

// Returns `format % args` as Python computes it (conversions s r a d i u f F e E g G x X o c %,
// flags, width and precision, `*` widths, mapping keys); throws EvalError on a mismatch
// ("not enough arguments for format string", ...).
std::string PercentFormat(const std::string& format, const Value& args);

}  // namespace urdfsnap::xacro
