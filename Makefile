# scanlab — two commands on a fresh machine: `make demo` and `make test`.
PYTHON ?= python3
VENV   := .venv
PY     := $(VENV)/bin/python
STAMP  := $(VENV)/.installed-$(shell cat pyproject.toml | cksum | cut -d' ' -f1)
OUT    ?= out/demo

.PHONY: demo test venv bench fuzz clean gallery

$(STAMP): pyproject.toml
	@test -x $(PY) || $(PYTHON) -m venv $(VENV)
	$(PY) -m pip install --quiet --upgrade pip
	$(PY) -m pip install --quiet -e '.[test,lessons,live]'
	@# bytecode made now, as pip makes it for an installed package: with PYTHONDONTWRITEBYTECODE
	@# set, every run compiled the ~40 modules a render imports (0.1-0.2 s of a 1.5 s warm start)
	$(PY) -m compileall -q lab renderer compare >/dev/null
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

# the scene loader against mutated presets; failing inputs go to out/fuzz/ (docs/bad-input.md)
CASES ?= 100000
SEED  ?= 1
fuzz: $(STAMP)
	$(PY) -m lab fuzz --cases $(CASES) --seed $(SEED) --save out/fuzz

# the README's gallery (docs/gallery/): panels carry no timings, so they come out the same bytes every time
GALLERY := out/gallery
gallery: $(STAMP)
	$(PY) -m lab compare spot-attenuation --size 320x240 --out $(GALLERY)/spot-attenuation
	$(PY) -m lab compare menger:level=3 --size 320x240 --out $(GALLERY)/menger-level3
	$(PY) -m lab compare painter-fails --size 320x240 --out $(GALLERY)/painter-fails
	$(PY) -m lab stages open-box --size 320x240 --out $(GALLERY)/open-box
	mkdir -p docs/gallery
	for s in spot-attenuation menger-level3 painter-fails; do cp $(GALLERY)/$$s/side_by_side.png docs/gallery/$$s.png; done
	cp $(GALLERY)/open-box/stages.png docs/gallery/open-box-stages.png

# compiled kernels are keyed by the renderer's sources (renderer/jit.py): nothing to clear by hand
clean:
	rm -rf $(VENV) out build *.egg-info renderer/__pycache__ "$${XDG_CACHE_HOME:-$$HOME/.cache}/scanlab/kernels"
