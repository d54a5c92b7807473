# Two entry points (README): `make demo` and `make test`. Both create .venv and install the project.
PY ?= python3
VENV := .venv
BIN := $(VENV)/bin
STAMP := $(VENV)/.installed

.PHONY: demo test test-bare-host test-python-hosts test-ssp-masters test-ehl-full lint fmus fmus-python-hosts report clean

$(STAMP): pyproject.toml
	$(PY) -m venv $(VENV)
	$(BIN)/python -m pip install -q --upgrade pip
	$(BIN)/python -m pip install -q -e ".[test,plot,sweep,cosim]"
	touch $(STAMP)

# FMUs are rebuilt only when a bundled source changed (or the environment was reinstalled)
FMU_SOURCES := $(shell find bearing_fmu bearing_fmu_common spindle -name '*.py' -o -name '*.toml' -o -name '*.c' | grep -v __pycache__)
FMU_STAMP := fmus/.built

$(FMU_STAMP): $(STAMP) $(FMU_SOURCES)
	$(BIN)/python -m spindle.cli build
	touch $@

fmus: $(FMU_STAMP)

# the FMUs with their kernels compiled for every supported Python (3.10-3.13, each found as python3.X on PATH
# or under pyenv): an environment of each under /tmp, made with pip once (docs/fmu_runtime.md, "Compiled code")
fmus-python-hosts: $(STAMP)
	BEARING_FMU_KERNEL_PYTHONS="$$($(BIN)/python -m bearing_fmu_common.runtime.host_pythons --others | paste -sd:)" \
		$(BIN)/python -m spindle.cli build
	touch $(FMU_STAMP)

demo: fmus
	$(BIN)/python -m spindle.cli demo --out results

lint: $(STAMP)
	$(BIN)/ruff check .
	$(BIN)/ruff format --check .

# no cache cleaning needed: the numba cache directory is keyed on the kernel sources (bearing_fmu_common/jit.py)
test: lint fmus
	$(BIN)/python -m pytest -q -m "not bare_host and not python_hosts and not ssp_masters and not ehl_full"

# the FMUs in a host with only fmpy, numpy and numba (a virtual environment under /tmp, made with pip once)
test-bare-host: fmus
	$(BIN)/python -m pytest -q -m bare_host

# the FMUs in fmpy and native hosts on Python 3.10, 3.11, 3.12 and 3.13 (an environment per Python under /tmp,
# made with pip once; the tests build their own FMUs with kernels for each)
test-python-hosts: $(STAMP)
	$(BIN)/python -m pytest -q -m python_hosts

# the exported SSP packages (closed_loop_spring, startup_dem) in ecos and OMSimulator against `spindle run`
# (an environment with ecospy under /tmp, made with pip once; OMSimulator from $OMSIMULATOR or the PATH, else its
# tests are skipped: README gives the commands that build it)
test-ssp-masters: fmus
	$(BIN)/python -m pytest -q -m ssp_masters

# the numerical EHL solver on all 55 Annexe D cases on its default grid (about 12 min on the shared machine)
test-ehl-full: $(STAMP)
	$(BIN)/python -m pytest -q -m ehl_full

# every benchmark, the stability suite and docs/report.md (benchmarks/report.py)
report: fmus
	$(BIN)/python -m benchmarks.report

clean:
	rm -rf $(VENV) fmus/*.fmu results .pytest_cache
