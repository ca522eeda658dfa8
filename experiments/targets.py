"""The declaration of the targets, experiments/targets.mk, read from Python.

targets.mk is the one place that says which targets exist, in which order, and which drivers (with which
extra arguments) produce each; Make includes it and the Python scripts (reference/check.py,
paper/build_report.py, tests/check_targets.py) read it through this module, so none of them keeps a list
of its own. The reader accepts only the lines the file's header describes and stops on anything else
(a Make construct it cannot evaluate would otherwise make Python and Make disagree silently):

    TARGETS += T ...                  T_DRIVERS := driver ...            T_ARGS := extra arguments
    T_RUN_DRIVER := the one of T's drivers whose runs are jobs of their own (the runs are its --list-runs)
    BENCH_DRIVERS += driver ...       blank lines, and '#' comments (also after a declaration)

tests/check_targets.py also compares this reading with Make's own (`make -s list-targets`).
"""
import os
import re

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PATH = os.path.join(ROOT, "experiments", "targets.mk")

_NAME = r"[A-Za-z0-9][A-Za-z0-9_.-]*"
_APPEND = re.compile(r"^(TARGETS|BENCH_DRIVERS)\s*\+=\s*(.*)$")
_ASSIGN = re.compile(rf"^({_NAME}?)_(DRIVERS|ARGS|RUN_DRIVER)\s*:=\s*(.*)$")
_LISTED_RUNS = re.compile(rf"^({_NAME}?)_(RUNS|RUN_ARGS)\s*:=")


class DeclarationError(ValueError):
    pass


class Target:
    def __init__(self, name):
        self.name, self.drivers, self.args = name, [], ""
        self.run_driver = ""  # the driver whose runs are jobs of their own (Makefile: run_rules)

    def __repr__(self):
        return f"Target({self.name!r}, drivers={self.drivers!r}, args={self.args!r}, run_driver={self.run_driver!r})"


class Declaration:
    def __init__(self, targets, bench_drivers, path):
        self.targets = targets              # [Target], in declaration order
        self.bench_drivers = bench_drivers  # [driver name]
        self.path = path

    @property
    def names(self):
        return [t.name for t in self.targets]


def read(path=PATH):
    """Parse targets.mk; raises DeclarationError (message 'path:line: ...') on anything not understood."""
    where = os.path.relpath(os.path.abspath(path), ROOT)
    targets, bench, seen = {}, [], {}
    assigned = []  # (line number, target, key, value), resolved once every TARGETS line is read
    with open(path) as f:
        for n, raw in enumerate(f, 1):
            line = raw.split("#", 1)[0].strip()  # as Make reads it: '#' starts a comment
            if not line:
                continue
            if "$" in line or line.endswith("\\"):
                raise DeclarationError(f"{where}:{n}: Make variables and continued lines are not part of the "
                                       f"declaration format: {line}")
            m = _APPEND.match(line)
            if m:
                names = m.group(2).split()
                for name in names:
                    if not re.fullmatch(_NAME, name):
                        raise DeclarationError(f"{where}:{n}: '{name}' is not a valid name")
                    if name in seen:
                        raise DeclarationError(f"{where}:{n}: {name} declared twice (first on line {seen[name]})")
                    seen[name] = n
                    if m.group(1) == "TARGETS":
                        targets[name] = Target(name)
                    else:
                        bench.append(name)
                continue
            if _LISTED_RUNS.match(line):
                raise DeclarationError(f"{where}:{n}: run names are not declared: the Makefile takes them from the "
                                       f"driver's --list-runs (declare T_RUN_DRIVER): {line}")
            m = _ASSIGN.match(line)
            if m:
                assigned.append((n, m.group(1), m.group(2), m.group(3).strip()))
                continue
            raise DeclarationError(f"{where}:{n}: not a declaration line (TARGETS +=, T_DRIVERS :=, T_ARGS :=, "
                                   f"T_RUN_DRIVER :=, BENCH_DRIVERS +=): {line}")
    done = set()
    for n, name, key, value in assigned:
        if name not in targets:
            raise DeclarationError(f"{where}:{n}: {name}_{key} for {name}, which no TARGETS line declares")
        if (name, key) in done:
            raise DeclarationError(f"{where}:{n}: {name}_{key} assigned twice")
        done.add((name, key))
        if key == "DRIVERS":
            targets[name].drivers = value.split()
        elif key == "ARGS":
            targets[name].args = value
        else:
            targets[name].run_driver = value
    for t in targets.values():
        if not t.drivers:
            raise DeclarationError(f"{where}: target {t.name} has no {t.name}_DRIVERS")
        if t.run_driver and t.run_driver not in t.drivers:
            raise DeclarationError(f"{where}: {t.name}_RUN_DRIVER must name one of its drivers ({' '.join(t.drivers)})")
    return Declaration(list(targets.values()), bench, path)
