#!/usr/bin/python3
"""Checks that every documented default of ISM_reconstruction_3 equals the code's.

The single source of the defaults is `struct Settings` in
include/CGAL/ISM_reconstruction_3/internal/settings.h (its member initializers, and
`Settings::paper()` for `paper_settings(true)`); `settings_from_parameters()` there maps
each named parameter to its member. This script parses them and compares:

  1. every `\\cgalParamDefault{...}` of a `\\cgalParamNBegin{name}` entry in the public
     headers (include/CGAL/*.h, include/CGAL/ISM_reconstruction_3/*.h and IO/*.h);
  2. the "Default" and "With paper_settings(true)" columns of the parameter table of the
     user manual (doc/ISM_reconstruction_3/ISM_reconstruction_3.txt);
  3. the list of the paper's values in the description of `paper_settings`;

and requires every named parameter to be documented in the doc of
`ism_surface_reconstruction()` and in the manual's table.

    check_defaults.py [repository root]

Exit status 0 if everything matches, 1 on any mismatch or omission, 2 if a file cannot be
parsed.
"""
import glob
import os
import re
import sys

SETTINGS_H = "include/CGAL/ISM_reconstruction_3/internal/settings.h"
MAIN_FUNCTION_H = "include/CGAL/ism_surface_reconstruction.h"
MANUAL = "doc/ISM_reconstruction_3/ISM_reconstruction_3.txt"
HEADER_GLOBS = ["include/CGAL/*.h", "include/CGAL/ISM_reconstruction_3/*.h",
                "include/CGAL/ISM_reconstruction_3/IO/*.h"]
# named parameters of CGAL whose defaults are not values of Settings
NOT_IN_SETTINGS = {"point_map", "geom_traits", "normal_map", "vertex_point_map"}


def fail_parse(msg):
    sys.stderr.write("check_defaults.py: cannot parse: %s\n" % msg)
    sys.exit(2)


def strip_comments(code):
    code = re.sub(r"/\*.*?\*/", "", code, flags=re.S)
    return re.sub(r"//[^\n]*", "", code)


def braced(text, start):
    """The text between the brace at `start` and its matching closing brace."""
    assert text[start] == "{"
    depth = 0
    for i in range(start, len(text)):
        if text[i] == "{":
            depth += 1
        elif text[i] == "}":
            depth -= 1
            if depth == 0:
                return text[start + 1:i], i
    fail_parse("unbalanced braces")


def parse_settings(root):
    src = open(os.path.join(root, SETTINGS_H)).read()
    code = strip_comments(src)
    m = re.search(r"struct\s+Settings\s*{", code)
    if not m:
        fail_parse("struct Settings in " + SETTINGS_H)
    body, _ = braced(code, m.end() - 1)
    # members: declarations at depth 0 of the struct body
    defaults, depth, statement = {}, 0, ""
    for ch in body:
        if ch == "{":
            depth += 1
        elif ch == "}":
            depth -= 1
            if depth == 0:
                statement = ""
            continue
        if depth > 0:
            continue
        if ch == ";":
            st = " ".join(statement.split())
            statement = ""
            dm = re.match(r"^(?:static\s+)?[\w:<>(), ]+?\s+(\w+)\s*(?:=\s*(.+))?$", st)
            if dm and "(" not in st.split("=")[0].replace("std::function<bool(double)>", ""):
                defaults[dm.group(1)] = dm.group(2).strip() if dm.group(2) else None
        else:
            statement += ch
    if not defaults:
        fail_parse("members of Settings")
    pm = re.search(r"static\s+Settings\s+paper\s*\(\s*\)\s*{", code)
    if not pm:
        fail_parse("Settings::paper()")
    paper_body, _ = braced(code, pm.end() - 1)
    paper = dict(defaults)
    for f, v in re.findall(r"\bs\.(\w+)\s*=\s*([^;]+);", paper_body):
        if f not in defaults:
            fail_parse("Settings::paper() sets unknown member " + f)
        paper[f] = v.strip()
    # named parameter -> member, from settings_from_parameters()
    fm = re.search(r"settings_from_parameters\s*\([^)]*\)\s*{", code)
    if not fm:
        fail_parse("settings_from_parameters()")
    from_np, _ = braced(code, fm.end() - 1)
    param_to_field = {}
    for field, tag, _ in re.findall(
            r"\bs\.(\w+)\s*=\s*(?:choose_parameter|internal::integer_parameter)\s*\(\s*get_parameter\s*\(\s*np\s*,\s*[\w:]*?(\w+)\s*\)\s*,"
            r"\s*([^;]+?)(?:,\s*\"\w+\")?\)\s*;", from_np):
        param_to_field[tag] = field
    ps = re.search(r"get_parameter\s*\(\s*np\s*,\s*[\w:]*paper_settings\s*\)\s*,\s*(\w+)\s*\)", from_np)
    if not ps:
        fail_parse("the default of paper_settings in settings_from_parameters()")
    if not param_to_field:
        fail_parse("the named parameters in settings_from_parameters()")
    return defaults, paper, param_to_field, ps.group(1)


def normalize(value):
    """A comparable form of a C++ literal or a documented value."""
    v = value.strip().strip("`").strip()
    v = re.sub(r"^(?:\w+::)+", "", v)  # CGAL::ISM_reconstruction_3::LOCAL_PLANE_DISTANCE
    num = re.sub(r"(?<=[0-9.])(?:[uU]?[lL]{0,2}|[fF])$", "", v)
    try:
        return ("number", float(num))
    except ValueError:
        return ("text", v)


def first_code(text):
    m = re.search(r"`([^`]+)`", text)
    return m.group(1) if m else None


def doc_entries(path):
    """(name, default text or None, description, line) of every \\cgalParamNBegin entry."""
    text = open(path).read()
    out = []
    for m in re.finditer(r"\\cgalParamNBegin\{(\w+)\}(.*?)\\cgalParamNEnd", text, re.S):
        block = m.group(2)
        line = text.count("\n", 0, m.start()) + 1

        def arg(cmd):
            k = block.find("\\" + cmd + "{")
            if k < 0:
                return None
            return " ".join(braced(block, k + len(cmd) + 1)[0].split())
        out.append((m.group(1), arg("cgalParamDefault"), arg("cgalParamDescription") or "", line))
    return out


def manual_rows(path):
    """(name, default, paper, line) of the rows of the manual's parameter table."""
    text = open(path).read()
    rows = []
    for m in re.finditer(r"<tr><td>`(\w+)`</td><td>(.*?)</td><td>(.*?)</td>", text):
        rows.append((m.group(1), m.group(2), m.group(3), text.count("\n", 0, m.start()) + 1))
    return rows


def main():
    root = os.path.abspath(sys.argv[1]) if len(sys.argv) > 1 else \
        os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
    defaults, paper, param_to_field, paper_settings_default = parse_settings(root)
    errors, checked = [], 0

    def expected(param, paper_column=False):
        if param == "paper_settings":
            return "true" if paper_column else paper_settings_default
        field = param_to_field.get(param)
        if field is None:
            return "<not a Settings parameter>"
        return (paper if paper_column else defaults)[field]

    def compare(where, param, documented, paper_column=False):
        nonlocal checked
        exp = expected(param, paper_column)
        if exp == "<not a Settings parameter>":
            return
        checked += 1
        code = first_code(documented) if documented is not None else None
        if exp is None:  # no initializer in the code (e.g. callback: an empty function)
            if code is not None and normalize(code) not in (("text", "nullptr"), ("text", "std::function<bool(double)>()")):
                errors.append("%s: `%s` is documented with the default `%s`, the code has none" % (where, param, code))
            return
        if code is None:
            errors.append("%s: no default in backquotes for `%s` (code: `%s`)" % (where, param, exp))
        elif normalize(code) != normalize(exp):
            errors.append("%s: `%s` documented default `%s` != code default `%s`%s"
                          % (where, param, code, exp, " (paper_settings)" if paper_column else ""))

    # 1. the reference manual (header docs)
    main_documented = set()
    for pattern in HEADER_GLOBS:
        for path in sorted(glob.glob(os.path.join(root, pattern))):
            rel = os.path.relpath(path, root)
            for name, default, description, line in doc_entries(path):
                where = "%s:%d" % (rel, line)
                if rel == MAIN_FUNCTION_H:
                    main_documented.add(name)
                if name not in param_to_field and name != "paper_settings":
                    continue
                if default is None:
                    errors.append("%s: `%s` has no \\cgalParamDefault" % (where, name))
                    continue
                compare(where, name, default)
                if name == "paper_settings":
                    listed = dict(re.findall(r"`(\w+)\(([^)`]+)\)`", description))
                    for field in sorted(f for f in paper if paper[f] != defaults[f]):
                        params = [p for p, f in param_to_field.items() if f == field]
                        if not any(p in listed for p in params):
                            errors.append("%s: the paper's value of `%s` is not listed in the description of "
                                          "`paper_settings`" % (where, field))
                    for p, v in listed.items():
                        checked += 1
                        if p not in param_to_field:
                            errors.append("%s: unknown parameter `%s` in the description of `paper_settings`"
                                          % (where, p))
                        elif normalize(v) != normalize(paper[param_to_field[p]]):
                            errors.append("%s: paper value of `%s` documented `%s` != code `%s`"
                                          % (where, p, v, paper[param_to_field[p]]))
    all_params = set(param_to_field) | {"paper_settings"}
    for p in sorted(all_params - main_documented):
        errors.append("%s: the named parameter `%s` is not documented (\\cgalParamNBegin)" % (MAIN_FUNCTION_H, p))
    for p in sorted(main_documented - all_params - NOT_IN_SETTINGS):
        errors.append("%s: `%s` is documented but settings_from_parameters() does not read it" % (MAIN_FUNCTION_H, p))

    # 2. the user manual's table
    rows = manual_rows(os.path.join(root, MANUAL))
    in_table = set()
    for name, default, paper_value, line in rows:
        in_table.add(name)
        where = "%s:%d" % (MANUAL, line)
        if name in NOT_IN_SETTINGS:
            continue
        if name not in all_params:
            errors.append("%s: `%s` in the parameter table is not a named parameter of Settings" % (where, name))
            continue
        compare(where, name, default)
        compare(where, name, paper_value, paper_column=True)
    for p in sorted(all_params - in_table):
        errors.append("%s: the named parameter `%s` is missing from the parameter table" % (MANUAL, p))

    for e in errors:
        print("MISMATCH " + e)
    print("check_defaults.py: %d named parameters, %d documented defaults compared, %d problem(s)"
          % (len(all_params), checked, len(errors)))
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
