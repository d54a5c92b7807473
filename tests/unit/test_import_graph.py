"""The product's modules import each other without a cycle (docs/architecture.md, layers).

A cycle, even through an import inside a function, means that two modules each need the other's names: neither can
be read, tested or replaced alone, and the order in which they are first imported decides what works. The graph is
read from the sources (every `import` and `from ... import` statement, at any depth, of bearing_fmu,
bearing_fmu_common and spindle); `from package import submodule` is an edge to the submodule only, as Python then
needs nothing of the package's own names.
"""

import ast
from pathlib import Path

from bearing_fmu.bundle import imports_of, package_modules

ROOT = Path(__file__).resolve().parents[2]
PACKAGES = ("bearing_fmu", "bearing_fmu_common", "spindle")


def _modules():
    """{dotted name: source file} of every module of the product."""
    return package_modules([(ROOT / package, package) for package in PACKAGES])


def import_graph():
    """{module: set of the product's modules it imports} (bearing_fmu.bundle: the same reading decides what an FMU
    carries)."""
    modules = _modules()
    return {name: imports_of(name, path, modules) for name, path in modules.items()}


def cycles(graph):
    """The strongly connected components of more than one module (Tarjan's algorithm, iterative)."""
    index, low, on_stack, stack, found = {}, {}, set(), [], []
    counter = 0
    for root in graph:
        if root in index:
            continue
        work = [(root, iter(sorted(graph[root])))]
        index[root] = low[root] = counter
        counter += 1
        stack.append(root)
        on_stack.add(root)
        while work:
            node, children = work[-1]
            child = next(children, None)
            if child is not None:
                if child not in index:
                    index[child] = low[child] = counter
                    counter += 1
                    stack.append(child)
                    on_stack.add(child)
                    work.append((child, iter(sorted(graph[child]))))
                elif child in on_stack:
                    low[node] = min(low[node], index[child])
                continue
            work.pop()
            if work:
                low[work[-1][0]] = min(low[work[-1][0]], low[node])
            if low[node] == index[node]:
                component = []
                while True:
                    member = stack.pop()
                    on_stack.discard(member)
                    component.append(member)
                    if member == node:
                        break
                if len(component) > 1:
                    found.append(sorted(component))
    return found


def test_the_walk_finds_a_cycle_when_there_is_one():
    """The finder itself: a three-module ring and a two-module one beside an acyclic branch are found, and nothing
    else."""
    graph = {"a": {"b"}, "b": {"c"}, "c": {"a", "d"}, "d": set(), "e": {"f"}, "f": {"e"}}
    assert sorted(cycles(graph)) == [["a", "b", "c"], ["e", "f"]]
    assert cycles({"a": {"b"}, "b": {"c"}, "c": set()}) == []


def test_the_product_has_no_import_cycle():
    """Every module of the product, imports inside functions included: no cycle."""
    graph = import_graph()
    assert "bearing_fmu.models.declarations" in graph and len(graph) > 50  # the walk saw the product
    assert cycles(graph) == []


TESTS = ROOT / "tests"
# the tests of the report's own code: they test benchmarks/, so they import it
REPORT_TESTS = {"tests/unit/test_report.py", "tests/unit/test_reference_table.py", "tests/unit/test_kernel_replay.py"}


def imports_benchmarks(source):
    """The import statements of a module's source (at any depth) that import the benchmarks package or a module of it,
    by their line numbers."""
    found = []
    for node in ast.walk(ast.parse(source)):
        if isinstance(node, ast.Import):
            names = [a.name for a in node.names]
        elif isinstance(node, ast.ImportFrom) and not node.level:
            names = [node.module or ""]
        else:
            continue
        if any(name == "benchmarks" or name.startswith("benchmarks.") for name in names):
            found.append(node.lineno)
    return found


def test_the_finder_sees_every_form_of_importing_the_benchmarks():
    source = (
        "import os\nfrom tests.cases import cwru\nimport benchmarks\nfrom benchmarks.ehl_solver import FLUID\n"
        "def f():\n    from benchmarks import report\n    import benchmarks.dem_steps as d\nfrom .benchmarks import x\n"
    )
    assert imports_benchmarks(source) == [3, 4, 6, 7]
    assert imports_benchmarks("import benchmarking\nfrom benchmarks_old import x\n") == []


def test_only_the_report_tests_import_the_benchmarks():
    """The tests own their validation cases (tests/cases/, docs/architecture.md section 5): a test module imports the
    product and tests/, and only the tests of the report's own code import benchmarks/."""
    offenders = {}
    for path in sorted(TESTS.rglob("*.py")):
        name = path.relative_to(ROOT).as_posix()
        if name not in REPORT_TESTS and (lines := imports_benchmarks(path.read_text(encoding="utf-8"))):
            offenders[name] = lines
    assert len(list(TESTS.rglob("test_*.py"))) > 100  # the walk saw the test suite
    assert offenders == {}
    for name in REPORT_TESTS:  # the exceptions are still what they are for
        assert imports_benchmarks((ROOT / name).read_text(encoding="utf-8")), name


# The layers, top to bottom (docs/architecture.md, its figure: benchmarks/architecture_figure.py): a module belongs to
# the layer of its longest matching prefix, and imports only modules of its own layer or of the layers below.
LAYERS = (
    ("command line", ("spindle", "spindle.cli", "spindle.check", "spindle.film_map", "spindle.configured")),
    ("co-simulation master", ("spindle.cosim",)),
    ("build", ("bearing_fmu.build", "bearing_fmu.bundle", "bearing_fmu.compiled_code", "bearing_fmu.fmu_files",
               "spindle.all_fmus", "bearing_fmu_common.runtime")),
    ("FMU slaves", ("bearing_fmu.fmu", "spindle.thermal.fmu", "spindle.shaft.fmu", "bearing_fmu_common.fmi",
                    "bearing_fmu_common.first_start")),
    ("fidelity registry", ("bearing_fmu.fidelities",)),
    ("models (facades, declarations, scenes, parameter files)", (
        "bearing_fmu", "bearing_fmu.models", "bearing_fmu.scene", "bearing_fmu.params", "spindle.thermal",
        "spindle.shaft",
        "bearing_fmu_common", "bearing_fmu_common.paramfile", "bearing_fmu_common.bearing_file",
        "bearing_fmu_common.variables",
    )),
    ("kernels", ("bearing_fmu.kernels", "spindle.thermal.network", "spindle.shaft.beam", "bearing_fmu_common.jit",
                 "bearing_fmu_common.layout")),
)  # fmt: skip


def layer_of(module):
    """Index in LAYERS of a module's layer (its longest matching prefix), None if none matches."""
    best = None
    for i, (_, prefixes) in enumerate(LAYERS):
        for prefix in prefixes:
            if (module == prefix or module.startswith(prefix + ".")) and (best is None or len(prefix) > best[1]):
                best = (i, len(prefix))
    return best[0] if best else None


def upward_imports(graph):
    """The imports (module, imported) that point to a higher layer."""
    return sorted((m, e) for m, edges in graph.items() for e in edges if layer_of(e) < layer_of(m))


def test_every_module_has_a_layer():
    assert [m for m in import_graph() if layer_of(m) is None] == []


def test_imports_point_down_the_layers():
    assert upward_imports(import_graph()) == []


def test_an_upward_import_is_found():
    assert upward_imports({"bearing_fmu.kernels.hertz": {"bearing_fmu.models.analytic"}}) == [
        ("bearing_fmu.kernels.hertz", "bearing_fmu.models.analytic")
    ]
