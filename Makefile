# scanlab — two commands on a fresh machine: `make demo` and `make test`.
PYTHON ?= python3
VENV   := .venv
PY     := $(VENV)/bin/python
STAMP  := $(VENV)/.installed-$(shell cat pyproject.toml | cksum | cut -d' ' -f1)
OUT    ?= out/demo

.PHONY: demo test venv bench fuzz clean clean-cache

$(STAMP): pyproject.toml
	@test -x $(PY) || $(PYTHON) -m venv $(VENV)
	$(PY) -m pip install --quiet --upgrade pip
	$(PY) -m pip install --quiet -e '.[test]'
	@rm -f $(VENV)/.installed-* && touch $@

venv: $(STAMP)

demo: $(STAMP)
	$(PY) -m lab demo --out $(OUT)

test: $(STAMP)
	$(PY) -m pytest -q

bench: $(STAMP)
	$(PY) -m lab bench icosphere:level=5 --size 512x512

# the scene loader against mutated presets; failing inputs go to out/fuzz/ (README, "Bad input")
CASES ?= 100000
SEED  ?= 1
fuzz: $(STAMP)
	$(PY) -m lab fuzz --cases $(CASES) --seed $(SEED) --save out/fuzz

# numba's on-disk cache is invalidated only when a kernel's *own* file changes: after
# editing a kernel that others call (say renderer/texture.py), clear it.
clean-cache:
	find lab renderer compare lessons -name '*.nbi' -delete -o -name '*.nbc' -delete

clean: clean-cache
	rm -rf $(VENV) out build *.egg-info
