# scanlab — two commands on a fresh machine: `make demo` and `make test`.
PYTHON ?= python3
VENV   := .venv
PY     := $(VENV)/bin/python
STAMP  := $(VENV)/.installed-$(shell cat pyproject.toml | cksum | cut -d' ' -f1)
OUT    ?= out/demo

.PHONY: demo test venv bench fuzz clean

$(STAMP): pyproject.toml
	@test -x $(PY) || $(PYTHON) -m venv $(VENV)
	$(PY) -m pip install --quiet --upgrade pip
	$(PY) -m pip install --quiet -e '.[test,lessons]'
	@rm -f $(VENV)/.installed-* && touch $@

venv: $(STAMP)

demo: $(STAMP)
	$(PY) -m lab demo --out $(OUT)
	$(PY) -m lab lessons build --out out/lessons

test: $(STAMP)
	$(PY) -m pytest -q

# issue 15's benchmark set against VTK; the table goes into README.md (section "Performance")
bench: $(STAMP)
	$(PY) -m lab bench --json out/bench.json --markdown README.md

# the scene loader against mutated presets; failing inputs go to out/fuzz/ (README, "Bad input")
CASES ?= 100000
SEED  ?= 1
fuzz: $(STAMP)
	$(PY) -m lab fuzz --cases $(CASES) --seed $(SEED) --save out/fuzz

# compiled kernels are keyed by the renderer's sources (renderer/jit.py): nothing to clear by hand
clean:
	rm -rf $(VENV) out build *.egg-info renderer/__pycache__ "$${XDG_CACHE_HOME:-$$HOME/.cache}/scanlab/kernels"
