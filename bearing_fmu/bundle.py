"""What an FMU carries of the product: the modules its entry script runs, read from their sources, and the data
files they read.

An FMU ships nothing it does not run (docs/fmu_runtime.md, What an FMU carries): not the build, the offline EHL
solver that builds the film tables, the command line or the master. The modules it carries are those its entry
imports (`entries`), with every module they import, at any depth and also inside functions, and the packages above
each; the data files are those under the `data` directories (the bearing and lubricant catalogue, the networks).
An import the sources do not spell out (importlib with a computed name) is not followed: the product's lazy public
names (`bearing_fmu.AnalyticModel`, ...) are for users of the package, not for its FMUs.
"""

import ast
from pathlib import Path


def package_modules(packages):
    """{dotted name: source file} of every module of `packages` ((directory, package name) pairs)."""
    found = {}
    for directory, package in packages:
        for path in Path(directory).rglob("*.py"):
            if "__pycache__" in path.parts:
                continue
            parts = [package, *path.relative_to(directory).with_suffix("").parts]
            if parts[-1] == "__init__":
                parts = parts[:-1]
            found[".".join(parts)] = path
    return found


def imported(name, path, node, modules):
    """The modules of `modules` that an import statement `node` of module `name` (file `path`) imports:
    `from package import submodule` imports the submodule, and the package itself only for names that are not
    submodules."""
    if isinstance(node, ast.Import):
        return [a.name for a in node.names if a.name in modules]
    base = name.split(".")
    if node.level:  # relative: a package's own __init__ counts as the package itself
        keep = len(base) - node.level + (1 if path.name == "__init__.py" else 0)
        base = base[:keep]
        target = ".".join(base + ([node.module] if node.module else []))
    else:
        target = node.module
    submodules = [f"{target}.{a.name}" for a in node.names if f"{target}.{a.name}" in modules]
    names = [target] if len(submodules) < len(node.names) and target in modules else []
    return submodules + names


def imports_of(name, path, modules):
    """The modules of `modules` that module `name` (file `path`) imports anywhere in its source."""
    found = set()
    for node in ast.walk(ast.parse(Path(path).read_text(encoding="utf-8"))):
        if isinstance(node, (ast.Import, ast.ImportFrom)):
            found.update(t for t in imported(name, path, node, modules) if t != name)
    return found


def run_modules(packages, entries):
    """The modules of `packages` that importing `entries` runs: each entry, what it imports, transitively, and the
    packages above each of them (importing a.b runs a/__init__.py first)."""
    modules = package_modules(packages)
    missing = [e for e in entries if e not in modules]
    if missing:
        raise ValueError(f"entry modules not in the bundled packages: {missing}")
    seen, todo = set(), list(entries)
    while todo:
        name = todo.pop()
        if name in seen:
            continue
        seen.add(name)
        parts = name.split(".")
        todo += [".".join(parts[:i]) for i in range(1, len(parts)) if ".".join(parts[:i]) in modules]
        todo += imports_of(name, modules[name], modules)
    return {name: modules[name] for name in sorted(seen)}


def runtime_bundle(packages, entries, data=()):
    """(source file, path in the FMU's resources/) of every file an FMU whose entry imports `entries` carries of
    `packages` ((directory, package name) pairs): the modules it runs (run_modules) and every file under the
    `data` directories (paths like "bearing_fmu/params": the package name, then the directory in it)."""
    roots = {package: Path(directory) for directory, package in packages}
    pairs = []
    for path in run_modules(packages, entries).values():
        package = next(p for p, root in roots.items() if path.is_relative_to(root))
        pairs.append((path, f"{package}/{path.relative_to(roots[package]).as_posix()}"))
    for entry in data:
        package, _, inside = entry.partition("/")
        for path in sorted((roots[package] / inside).rglob("*")):
            if path.is_file() and path.suffix != ".py" and "__pycache__" not in path.parts:
                pairs.append((path, f"{package}/{path.relative_to(roots[package]).as_posix()}"))
    return tuple(pairs)
