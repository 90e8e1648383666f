#!/usr/bin/python3
"""Every threshold of a thresholds file derived, labelled by construction, or a
known breach (issue 25, item 1; the format is in cases/thresholds.toml's header).

    threshold_derivations.py cases/thresholds.toml

Evaluates the [constants] (in order; each may use those above it) and every
`bound` with a small evaluator over Python's AST (numbers, + - * / **, unary
minus, parentheses, a fixed set of functions, pi and the constants: nothing
else is run), then checks each [[threshold]]:
  - a bound (derived), by_construction = true with its bound (what holds by
    construction still rounds), or known_breach (which may carry the bound
    of the band it is judged against);
  - atol or rtol, never both; t = rtol if set, else atol;
  - with a bound b: b finite and >= 0; t >= b (no band tighter than its
    bound); t <= max(1.1 b, b rounded up to 2 significant digits) (no pad);
    b = 0 requires t = 0;
  - a why without the phrases the format forbids (a pad, interpolation, a
    band quoted from an issue);
  - a known breach states its expected range (expected, expected_bound,
    expected_why), each end no tighter than its expression and not padded;
  - a bound that assumes a run's accepted steps or a collider's depth error
    states it (steps_at_most, depth_error_at_most) for `check` to test;
  - every case with a band against "truth" is listed in [truths];
  - every constant has a source comment, and one that is a measurement names
    the test that recomputes it (or the record `check` tests).
Prints the table total / derived / by construction / known breach / other per
engine and for the file; exits 1 when other > 0 (naming each offending
threshold and why) or a constant does not evaluate. A self-test runs first so
the checks themselves can be seen to fail.
"""

import ast
import math
import re
import sys
import tomllib

FUNCTIONS = {
    "sqrt": math.sqrt, "exp": math.exp, "log": math.log, "sin": math.sin, "cos": math.cos,
    "tan": math.tan, "asin": math.asin, "acos": math.acos, "atan": math.atan, "abs": abs,
    "min": min, "max": max,
}
BINARY = {
    ast.Add: lambda a, b: a + b, ast.Sub: lambda a, b: a - b, ast.Mult: lambda a, b: a * b,
    ast.Div: lambda a, b: a / b, ast.Pow: lambda a, b: a ** b,
}
# exponents in bounds are small integers (squares, halves); a larger one is a slip
# and could make ** run for long on an integer base
MAX_EXPONENT = 16.0
# a band written out as its bound's decimal may differ from the evaluated bound
# by the rounding of a double (2.2e-16 relative); 1e-12 is far above that and far
# below any real difference between a band and its bound
REL_ROUNDING = 1e-12
# phrases the format forbids in a why (cases/thresholds.toml's header)
FORBIDDEN = [
    (re.compile(r"\bissues?[- ]?\d+", re.I),
     "a band quoted from an issue (derive it; an issue is not a source)"),
    (re.compile(r"\+\s*1\s*%"), "a pad ('+ 1 %')"),
    (re.compile(r"\bpad(ded)?\b", re.I), "a pad"),
    (re.compile(r"between the last", re.I), "interpolation between other cases"),
    (re.compile(r"no closed-form bound", re.I), "no bound stated"),
]


class BoundError(Exception):
    pass


# a bound is a line of arithmetic; far longer is not one (and Python's parser
# and this evaluator recurse: 1e5 unary minus signs exhaust the stack)
MAX_EXPRESSION_CHARS = 2000


def evaluate(text, names):
    """The value of expression `text` over `names` (a dict); BoundError if not allowed."""
    text = text.strip()
    if len(text) > MAX_EXPRESSION_CHARS:
        raise BoundError(f"{len(text)} characters; an expression has at most "
                         f"{MAX_EXPRESSION_CHARS}")
    try:
        tree = ast.parse(text, mode="eval")
    except SyntaxError as e:
        raise BoundError(f"not an expression: {e.msg}") from None
    except (RecursionError, MemoryError):
        raise BoundError("nested too deeply to evaluate") from None

    def ev(node):
        if isinstance(node, ast.Expression):
            return ev(node.body)
        if isinstance(node, ast.Constant):
            if isinstance(node.value, bool) or not isinstance(node.value, (int, float)):
                raise BoundError(f"only numbers are allowed, not {node.value!r}")
            try:
                return float(node.value)
            except OverflowError:
                raise BoundError(f"the number {str(node.value)[:20]}... does not fit a "
                                 "double") from None
        if isinstance(node, ast.Name):
            if node.id == "pi":
                return math.pi
            if node.id in names:
                return names[node.id]
            raise BoundError(f"unknown name '{node.id}' (not pi, nor a constant above it)")
        if isinstance(node, ast.UnaryOp) and isinstance(node.op, (ast.USub, ast.UAdd)):
            v = ev(node.operand)
            return -v if isinstance(node.op, ast.USub) else v
        if isinstance(node, ast.BinOp) and type(node.op) in BINARY:
            a, b = ev(node.left), ev(node.right)
            if isinstance(node.op, ast.Pow) and abs(b) > MAX_EXPONENT:
                raise BoundError(f"exponent {b:g} is larger than {MAX_EXPONENT:g}")
            try:
                v = BINARY[type(node.op)](a, b)
            except (ZeroDivisionError, OverflowError) as e:
                raise BoundError(str(e)) from None
            if isinstance(v, complex):
                raise BoundError(f"'{ast.unparse(node)}' is complex (a negative base to a "
                                 "fractional power)")
            return float(v)
        if isinstance(node, ast.Call):
            if not isinstance(node.func, ast.Name) or node.func.id not in FUNCTIONS:
                raise BoundError(f"unknown function in '{ast.unparse(node)}'; allowed: "
                                 + " ".join(FUNCTIONS))
            if node.keywords or not node.args:
                raise BoundError(f"'{ast.unparse(node)}': give positional arguments only")
            args = [ev(a) for a in node.args]
            try:
                return float(FUNCTIONS[node.func.id](*args))
            except (ValueError, TypeError, OverflowError) as e:
                raise BoundError(f"'{ast.unparse(node)}': {e}") from None
        raise BoundError(f"'{ast.unparse(node)}' is not allowed (numbers, + - * / **, "
                         "functions, pi and constants only)")

    try:
        v = ev(tree)
    except (RecursionError, MemoryError):
        raise BoundError("nested too deeply to evaluate") from None
    if isinstance(v, complex):
        raise BoundError("the value is complex")
    return v


# a constant's source that is a measurement, not a derivation (issue 31): it
# passes only where the comment names the test that recomputes it from the
# code that produces it ("tests/...") or the run record `check` tests
MEASURED = re.compile(r"\bmeasured\b|\bobserved\b|rounded up|worst of|as seen", re.I)
RECOMPUTED = re.compile(r"tests/|check tests it")


def constant_sources(text):
    """(offences) of the [constants] section of a thresholds file's text: every
    constant has a source (a comment on its line, or the comment lines above
    its group, which a blank line ends); a measured figure names the test that
    recomputes it or the record check tests"""
    start = text.find("[constants]\n")
    end = text.find("# end of constants", start)
    if start < 0 or end < 0:
        return []
    offences, pending = [], []
    for line in text[start + len("[constants]\n"):end].split("\n"):
        stripped = line.strip()
        if not stripped:
            pending = []
            continue
        if stripped.startswith("#"):
            pending.append(stripped)
            continue
        m = re.match(r'([A-Za-z_][A-Za-z0-9_]*)\s*=\s*"[^"]*"\s*(#.*)?$', stripped)
        if not m:
            continue
        comment = " ".join(pending + ([m.group(2)] if m.group(2) else []))
        if not comment:
            offences.append(f"constants.{m.group(1)}: no source (a comment on its line or above "
                            "its group)")
        elif MEASURED.search(comment) and not RECOMPUTED.search(comment):
            offences.append(f"constants.{m.group(1)}: a measured figure; derive it, or name the "
                            "test that recomputes it (tests/...) or the record check tests")
    return offences


def evaluate_constants(table):
    """(values, errors): each constant over those above it."""
    values, errors = {}, []
    if not isinstance(table, dict):
        return values, [f"constants: must be a table of name = \"expression\" (got {table!r:.40})"]
    for name, text in table.items():
        if not isinstance(text, str):
            errors.append(f"constants.{name}: must be a string expression (got {text!r})")
            continue
        if name == "pi" or name in FUNCTIONS:
            errors.append(f"constants.{name}: the name is taken by pi or a function")
            continue
        try:
            v = evaluate(text, values)
        except BoundError as e:
            errors.append(f"constants.{name} = \"{text[:80]}\": {e}")
            continue
        if not math.isfinite(v):
            errors.append(f"constants.{name} = \"{text[:80]}\": evaluates to {v}; a constant "
                          "is a finite number")
            continue
        values[name] = v
    return values, errors


def round_up_2_significant(b):
    if b <= 0:
        return b
    unit = 10.0 ** (math.floor(math.log10(b)) - 1)
    return math.ceil(b / unit * (1 - REL_ROUNDING)) * unit


def round_out_2_significant(b, up):
    """b rounded to 2 significant digits away from the range's inside (up: towards
    +inf for a top, else towards -inf for a bottom)"""
    if b == 0:
        return b
    if (b > 0) == up:
        return math.copysign(round_up_2_significant(abs(b)), b)
    unit = 10.0 ** (math.floor(math.log10(abs(b))) - 1)
    return math.copysign(math.floor(abs(b) / unit * (1 + REL_ROUNDING)) * unit, b)


def expected_problems(th, constants):
    """A known breach's expected range: `expected = [min, max]` the metric's value
    its mechanism gives, `expected_bound` the two expressions it comes from,
    `expected_why` the words; each end no tighter than its expression and not
    padded beyond it (10 % of it or its rounding outwards to 2 digits)."""
    keys = ("expected", "expected_bound", "expected_why")
    if not th.get("known_breach"):
        return [f"{k} without known_breach" for k in keys if k in th]
    problems = [f"known breach without {k}: state the range its mechanism gives"
                for k in keys if not th.get(k)]
    if problems:
        return problems
    rng, exprs = th["expected"], th["expected_bound"]
    if not (isinstance(rng, list) and len(rng) == 2 and all(
            isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v)
            for v in rng)):
        return [f"expected = {rng!r}: give [min, max], two finite numbers"]
    if not isinstance(th["expected_why"], str):
        return [f"expected_why = {th['expected_why']!r}: give the mechanism in words (a string)"]
    if not (isinstance(exprs, list) and len(exprs) == 2 and all(isinstance(e, str) for e in exprs)):
        return [f"expected_bound = {exprs!r}: give two expressions as strings"]
    ends = []
    for text in exprs:
        try:
            ends.append(evaluate(text, constants))
        except BoundError as e:
            problems.append(f"expected_bound \"{text[:80]}\": {e}")
    if problems:
        return problems
    lo_b, hi_b = ends
    lo, hi = float(rng[0]), float(rng[1])
    if not (math.isfinite(lo_b) and math.isfinite(hi_b)) or lo_b > hi_b:
        return [f"expected_bound evaluates to [{lo_b:.6g}, {hi_b:.6g}]: must be finite, min <= max"]
    slack = REL_ROUNDING * max(abs(lo_b), abs(hi_b), 1e-300)
    if lo > lo_b + slack:
        problems.append(f"expected min {lo:g} is tighter than its bound {lo_b:.6g}")
    elif lo < min(lo_b - 0.1 * abs(lo_b), round_out_2_significant(lo_b, False)) - slack:
        problems.append(f"expected min {lo:g} is padded below its bound {lo_b:.6g}")
    if hi < hi_b - slack:
        problems.append(f"expected max {hi:g} is tighter than its bound {hi_b:.6g}")
    elif hi > max(hi_b + 0.1 * abs(hi_b), round_out_2_significant(hi_b, True)) + slack:
        problems.append(f"expected max {hi:g} is padded above its bound {hi_b:.6g}")
    return problems


def constants_used(expr, table):
    """every constant of `table` an expression uses, directly or through others
    (a constant defined through itself or a cycle is visited once: its
    evaluation reports it, evaluate_constants)"""
    out, todo = set(), [expr]
    while todo:
        for name in set(re.findall(r"[A-Za-z_][A-Za-z0-9_]*", todo.pop())):
            if name in table and isinstance(table[name], str) and name not in out:
                out.add(name)
                todo.append(table[name])
    return out


# what a bound may assume of the run's own figures (issue 31), each stated as
# a key `check` tests on the run: (key, the constants that assume it, the
# figure in words); the least such constant is the value the key must state
RUN_ASSUMPTIONS = (
    ("steps_at_most", re.compile(r"steps"), "accepted steps"),
    ("depth_error_at_most", re.compile(r"_mpr_err$"), "m of depth error"),
)


def assumption_problems(th, constants, table):
    """a bound that uses a constant assuming a run's figure (a *steps* constant:
    the accepted steps; a *_mpr_err one: the collider's recorded depth error)
    states it under the key `check` tests; no such key without such a bound"""
    used_all = constants_used(str(th.get("bound", "")), table)
    problems = []
    for key, pattern, what in RUN_ASSUMPTIONS:
        used = {n for n in used_all if pattern.search(n)}
        have = th.get(key)
        if not used:
            if have is not None:
                problems.append(f"{key} without a bound that assumes it")
            continue
        want = min(constants[n] for n in used if n in constants)
        if have != want:
            problems.append(f"the bound assumes at most {want:g} {what} "
                            f"({', '.join(sorted(used))}): state {key} = {want:g} (got {have!r})")
    return problems


def classify(th, constants, table=None):
    """(category, problems): category one of derived, by_construction, known_breach, other."""
    problems = []
    has_bound = "bound" in th
    by_construction = th.get("by_construction") is True
    known = bool(th.get("known_breach"))
    labels = [n for n, on in (("bound", has_bound), ("by_construction", by_construction),
                              ("known_breach", known)) if on]
    if known and labels == ["bound", "known_breach"]:
        category = "known_breach"
    elif labels == ["bound", "by_construction"]:
        category = "by_construction"
    elif labels == ["by_construction"]:
        category = "other"
        problems.append("by_construction without a bound: state the rounding (or other) bound "
                        "that what holds by construction still has")
    elif len(labels) == 1:
        category = {"bound": "derived", "by_construction": "by_construction",
                    "known_breach": "known_breach"}[labels[0]]
    elif not labels:
        category = "other"
        problems.append("none of bound, by_construction = true, known_breach: derive it")
    else:
        category = "other"
        problems.append(f"{' and '.join(labels)}: give exactly one (a known breach may add a bound)")
    if "atol" in th and "rtol" in th:
        problems.append("sets both atol and rtol: give one")
    t = th.get("rtol", th.get("atol"))
    if not isinstance(t, (int, float)) or isinstance(t, bool):
        problems.append("no numeric atol or rtol")
        t = None
    problems += expected_problems(th, constants)
    problems += assumption_problems(th, constants, table or {})
    why = th.get("why", "")
    for pattern, what in FORBIDDEN:
        if pattern.search(why):
            problems.append(f"why contains {what}")
    if has_bound:
        try:
            b = evaluate(str(th["bound"]), constants)
        except BoundError as e:
            b = None
            problems.append(f"bound \"{str(th['bound'])[:80]}\": {e}")
        if b is not None:
            if not math.isfinite(b) or b < 0:
                problems.append(f"bound evaluates to {b:g}: must be finite and >= 0")
            elif t is not None:
                kind = "rtol" if "rtol" in th else "atol"
                upper = max(1.1 * b, round_up_2_significant(b))
                if b == 0 and t != 0:
                    problems.append(f"bound is 0 but {kind} = {t:g}: must be 0")
                elif t < b * (1 - REL_ROUNDING):
                    problems.append(f"{kind} = {t:g} is tighter than its bound {b:.6g}")
                elif t > upper * (1 + REL_ROUNDING):
                    problems.append(f"{kind} = {t:g} is padded: bound {b:.6g}, at most "
                                    f"{upper:.6g} (1.1 b or b rounded up to 2 digits)")
    return ("other" if problems else category), problems


def name_of(th):
    ep = th.get("episode")
    return (f"{th.get('case')}.{th.get('engine')} {th.get('metric')} vs {th.get('against')}"
            f" [episode {'all' if ep is None else ep}]")


def check(doc):
    """(rows per engine, offences, constant errors)."""
    constants, errors = evaluate_constants(doc.get("constants", {}))
    counts, offences = {}, []
    truths = doc.get("truths", {})
    if not isinstance(truths, dict):
        offences.append(f"[truths] must be a table of case = \"kind\" (got {truths!r:.40})")
        truths = {}
    thresholds = doc.get("threshold", [])
    if not isinstance(thresholds, list):
        offences.append(f"threshold must be an array of tables, [[threshold]] (got {thresholds!r:.40})")
        thresholds = []
    for i, th in enumerate(thresholds):
        if not isinstance(th, dict):
            offences.append(f"threshold[{i}] must be a table, [[threshold]] (got {th!r:.40})")
    thresholds = [th for th in thresholds if isinstance(th, dict)]
    for case in sorted({str(th.get("case")) for th in thresholds
                        if th.get("against") == "truth"}):
        if case not in truths:
            offences.append(f"[truths] does not list {case}: state the kind of truth its bands "
                            "against \"truth\" were derived with")
    for th in thresholds:
        table = doc.get("constants", {})
        category, problems = classify(th, constants, table if isinstance(table, dict) else {})
        row = counts.setdefault(th.get("engine", "?"), dict.fromkeys(
            ("derived", "by_construction", "known_breach", "other"), 0))
        row[category] += 1
        if problems:
            offences.append(f"{name_of(th)}: {'; '.join(problems)}")
    return counts, offences, errors


def self_test():
    """The checks catch an underived, a padded and a too-tight entry; a good one passes."""
    head = ('[constants]\nh = "1e-4"\nomega = "sqrt(1e4 / 1.0)"\nomega_h = "omega * h"\n'
            'ref_steps = "1000"\n# end of constants\n[truths]\nc = "closed form"\n')

    def entry(extra):
        return ('[[threshold]]\ncase = "c"\nengine = "e"\nagainst = "truth"\n'
                f'metric = "peak_force"\nwhy = "w"\n{extra}\n')

    cases = {
        "good": (entry('rtol = 0.01\nbound = "omega_h"'), 0),
        "good, rounded up": (entry('rtol = 0.0105\nbound = "omega_h * 1.04"'), 0),
        "underived": (entry("rtol = 0.01"), 1),
        "padded": (entry('rtol = 0.02\nbound = "omega_h"'), 1),
        "too tight": (entry('rtol = 0.009\nbound = "omega_h"'), 1),
        "both tolerances": (entry('rtol = 0.01\natol = 0.01\nbound = "omega_h"'), 1),
        "zero bound, nonzero band": (entry('atol = 1e-9\nbound = "0"'), 1),
        "code in a bound": (entry('rtol = 0.01\nbound = "__import__(\'os\').getpid()"'), 1),
        "unknown name": (entry('rtol = 0.01\nbound = "omega_k"'), 1),
        "by construction with its bound": (entry('rtol = 0.01\nbound = "omega_h"\n'
                                                 "by_construction = true"), 0),
        "by construction without a bound": (entry("rtol = 0.01\nby_construction = true"), 1),
        "known breach with its band and range": (entry(
            'rtol = 0.01\nbound = "omega_h"\nknown_breach = "k"\nexpected = [0.0, 2.1]\n'
            'expected_bound = ["0", "2 * 1.04"]\nexpected_why = "m"'), 0),
        "known breach without a range": (entry('rtol = 0.01\nbound = "omega_h"\n'
                                               'known_breach = "k"'), 1),
        "known breach, range tighter than its bound": (entry(
            'rtol = 0.01\nbound = "omega_h"\nknown_breach = "k"\nexpected = [0.0, 2.0]\n'
            'expected_bound = ["0", "2 * 1.04"]\nexpected_why = "m"'), 1),
        "known breach, range padded": (entry(
            'rtol = 0.01\nbound = "omega_h"\nknown_breach = "k"\nexpected = [-1.0, 2.1]\n'
            'expected_bound = ["0.5", "2 * 1.04"]\nexpected_why = "m"'), 1),
        "a range without a known breach": (entry(
            'rtol = 0.01\nbound = "omega_h"\nexpected = [0.0, 2.1]\n'
            'expected_bound = ["0", "2 * 1.04"]\nexpected_why = "m"'), 1),
        "a step count assumed, not stated": (entry('rtol = 0.01\nbound = "ref_steps * 1e-5"'), 1),
        "a step count assumed and stated": (entry('rtol = 0.01\nbound = "ref_steps * 1e-5"\n'
                                                  'steps_at_most = 1000'), 0),
        "an issue's band in the why": (entry('rtol = 0.01\nbound = "omega_h"').replace(
            'why = "w"', 'why = "the issue-16 generality band for peak force"'), 1),
        "a pad in the why": (entry('rtol = 0.01\nbound = "omega_h"').replace(
            'why = "w"', 'why = "omega h + 1 %"'), 1),
    }
    failures = []
    for label, (text, want) in cases.items():
        _, offences, errors = check(tomllib.loads(head + text))
        if errors or len(offences) != want:
            failures.append(f"self-test '{label}': {len(offences)} offence(s) {offences}, "
                            f"expected {want}; constant errors {errors}")
    _, offences, _ = check(tomllib.loads(head.replace('[truths]\nc = "closed form"\n', "")
                                         + cases["good"][0]))
    if len(offences) != 1 or "[truths]" not in offences[0]:
        failures.append(f"self-test: a case missing from [truths] was not named: {offences}")
    sources = {
        "a measured-error constant": ('[constants]\nerr = "0.00289 * 1.5"  # the measured error x 1.5\n'
                                      "# end of constants\n", 1),
        "a constant without a source": ('[constants]\nerr = "0.00289"\n# end of constants\n', 1),
        "a measured figure a test recomputes": (
            '[constants]\nerr = "1e-6"  # measured worst 5.3e-7, asserted by tests/x_test.cpp\n'
            "# end of constants\n", 0),
        "a derived constant": ('[constants]\n# the ball (case file)\nm = "1"\nw = "sqrt(m)"\n'
                               "# end of constants\n", 0),
    }
    for label, (text, want) in sources.items():
        got = constant_sources(text)
        if len(got) != want:
            failures.append(f"self-test '{label}': {len(got)} offence(s) {got}, expected {want}")
    for label, text in {
        "a complex power": "(-8)**0.5",
        "a 400-digit literal": "1" * 400,
        "a 50,000-term sum": "+".join(["1"] * 50000),
        "1e5 unary minus signs": "-" * 100000 + "1",
    }.items():
        try:
            evaluate(text, {})
            failures.append(f"self-test '{label}': accepted")
        except BoundError:
            pass
    for label, doc in {
        "constants that are not a table": 'constants = "x"\n',
        "a constant that overflows": '[constants]\nbig = "1e300 * 1e300"\n',
    }.items():
        if not check(tomllib.loads(doc))[2]:
            failures.append(f"self-test '{label}': accepted")
    _, _, errors = check(tomllib.loads('[constants]\na = "b + 1"\nb = "1"\n'))
    if not errors:
        failures.append("self-test: a constant using one defined below it was accepted")
    # issue 49: each of these ended in a traceback; each is one line now
    for label, doc in {
        "a constant defined through itself": '[constants]\na = "a + 1"\n' + entry('rtol = 1\nbound = "a"'),
        "a cycle of constants": '[constants]\na = "b"\nb = "a"\n' + entry('rtol = 1\nbound = "a"'),
        "a threshold given as a string": 'threshold = "x"\n',
        "a threshold array holding a string": 'threshold = ["x"]\n',
        "an expected range holding NaN": entry(
            'rtol = 0.01\nbound = "1"\nknown_breach = "k"\nexpected = [nan, 2.1]\n'
            'expected_bound = ["0", "2"]\nexpected_why = "m"'),
        "expected_why a number": entry(
            'rtol = 0.01\nbound = "1"\nknown_breach = "k"\nexpected = [0.0, 2.1]\n'
            'expected_bound = ["0", "2"]\nexpected_why = 5'),
    }.items():
        try:
            _, offences, errors = check(tomllib.loads(doc))
        except Exception as e:  # noqa: BLE001 - the self-test reports any traceback
            failures.append(f"self-test '{label}': raised {type(e).__name__}: {e}")
            continue
        if not offences and not errors:
            failures.append(f"self-test '{label}': accepted")
    if abs(round_up_2_significant(0.0314159) - 0.032) > 1e-15 or \
            abs(round_up_2_significant(0.03) - 0.03) > 1e-15:
        failures.append("self-test: rounding up to 2 significant digits is wrong")
    return failures


def main(argv):
    if len(argv) != 2:
        print("usage: threshold_derivations.py THRESHOLDS.toml", file=sys.stderr)
        return 2
    failures = self_test()
    if failures:
        print("\n".join(failures))
        return 1
    try:
        with open(argv[1], "rb") as f:
            raw = f.read()
        doc = tomllib.loads(raw.decode("utf-8"))
    except (OSError, UnicodeDecodeError, tomllib.TOMLDecodeError) as e:
        print(f"{argv[1]}: {e}")
        return 1
    counts, offences, errors = check(doc)
    offences += constant_sources(raw.decode("utf-8"))
    cols = ("derived", "by_construction", "known_breach", "other")
    print(f"{'engine':<12} {'total':>6} {'derived':>8} {'by constr.':>10} {'known br.':>9} "
          f"{'other':>6}")
    total = dict.fromkeys(cols, 0)
    for engine in sorted(counts):
        row = counts[engine]
        for c in cols:
            total[c] += row[c]
        print(f"{engine:<12} {sum(row.values()):>6} {row['derived']:>8} "
              f"{row['by_construction']:>10} {row['known_breach']:>9} {row['other']:>6}")
    print(f"{'all':<12} {sum(total.values()):>6} {total['derived']:>8} "
          f"{total['by_construction']:>10} {total['known_breach']:>9} {total['other']:>6}")
    for e in errors:
        print(f"{argv[1]}: {e}")
    for o in offences:
        print(f"{argv[1]}: {o}")
    return 1 if offences or errors else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
