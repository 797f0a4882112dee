# Two-command quick start: `make demo` runs the main job, `make test` runs the tests.
PY ?= python3.11
VENV ?= .venv
BIN := $(VENV)/bin
OUT ?= out/demo

.PHONY: install demo test release-check lint bench clean

$(BIN)/luminous: pyproject.toml
	$(PY) -m venv $(VENV) || python3 -m venv $(VENV)
	$(BIN)/pip install --quiet --upgrade pip
	$(BIN)/pip install --quiet -e '.[test,export,view]'
	# the learned speaker's tests need torch; the CPU build is installed by exact version (never a CUDA one)
	$(BIN)/pip install --quiet torch==2.13.0 || echo "torch==2.13.0 unavailable: the speaker tests will skip"
	# RL and offline RL (the `learn` and `minari` extras), after torch so that pip keeps that torch
	$(BIN)/pip install --quiet -e '.[learn,minari]' || echo "stable-baselines3/minari unavailable: their tests will skip"
	touch $(BIN)/luminous

install: $(BIN)/luminous

demo: install
	$(BIN)/luminous demo --out $(OUT) --seed 0

test: install
	$(BIN)/ruff check luminous_sim tests benchmarks scripts examples
	$(BIN)/mypy
	$(BIN)/python -m pytest -q -m "not slow" -n auto --dist worksteal tests  # pytest-xdist: one worker a core; idle workers take queued tests from busy ones

# the release path: sdist and wheel built and checked, the wheel installed in a fresh venv and tried from outside
# the repository (scripts/release_check.sh)
release-check: install
	PY=$(PY) bash scripts/release_check.sh

lint: install
	$(BIN)/ruff check luminous_sim tests benchmarks scripts examples
	$(BIN)/mypy

bench: install
	for f in benchmarks/bench_*.py; do $(BIN)/python $$f || exit 1; done

clean:
	rm -rf $(VENV) out .pytest_cache
