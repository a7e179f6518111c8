# stiefelsym: the two commands a new user needs are `make verify` and `make test`.
PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed
#: worker processes for the verification runs (the verdicts do not depend on it)
JOBS   ?= 2
#: make verify covers every size n <= MAX_N each claim is stated for
MAX_N  ?= 6

.PHONY: venv verify verify-all test bench report clean tables flows speed paper-labels

## venv: create .venv (if missing) and install stiefelsym with its test extras; compile the
## bytecode (where PYTHONDONTWRITEBYTECODE is set, e.g. CI images, every start would recompile)
venv: $(STAMP)
	$(BIN)/python -m compileall -q stiefelsym proofs bench > /dev/null

$(STAMP): pyproject.toml
	test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet -e '.[test,lint]'
	touch $(STAMP)

## verify: verify the whole catalog (default methods) at every size n <= MAX_N and regenerate reports/
verify: venv
	$(BIN)/stiefelsym verify --jobs $(JOBS) --max-n $(MAX_N) --report-dir reports

## verify-all: every method at every size (auto, modular, rational, float, free) and the slow tests
verify-all: venv
	$(BIN)/stiefelsym verify --jobs $(JOBS) --method auto --method modular --method rational --method float --method free \
		--report-dir reports/all
	$(MAKE) test-slow

#: pytest-xdist processes of make test (TEST_JOBS=0: serial)
TEST_JOBS ?= 2

## test: the test suite without the tests marked slow, in TEST_JOBS processes (pytest exit 5, "no
## tests", is not a failure)
test: venv
	$(BIN)/python -m pytest -q $(if $(filter 0,$(TEST_JOBS)),,-n $(TEST_JOBS)) || test $$? -eq 5

## test-slow: the tests marked slow (larger sizes, more methods, the adversary rounds' longer replays), in
## TEST_JOBS processes (make verify-all runs them)
.PHONY: test-slow
test-slow: venv
	$(BIN)/python -m pytest -q -m slow $(if $(filter 0,$(TEST_JOBS)),,-n $(TEST_JOBS)) || test $$? -eq 5

## lint: ruff (the configuration in pyproject.toml) and mypy on the public API
.PHONY: lint
lint: venv
	$(BIN)/python -m ruff check .
	$(BIN)/python -m mypy

## bench: timings of the verification methods, and Singular's Gröbner reduction of LA1 beside the exact
## method where Singular is installed (bench/singular.py)
bench: venv
	$(BIN)/python bench/bench.py
	$(BIN)/python bench/singular.py

## mutate: mutation analysis of the catalog (small corruptions every method must catch); writes reports/mutation.{json,md}
.PHONY: mutate
mutate: venv
	$(BIN)/stiefelsym mutate --jobs $(JOBS) --report-dir reports

## discover: the corrections of the paper's printed formulas as solution spaces in reports/discover.{md,tex}
## (16-40 s, so not part of verify)
.PHONY: discover
discover: venv
	$(BIN)/stiefelsym discover --correct all --report-dir reports
	$(BIN)/stiefelsym discover --tables --report-dir reports

## tables: appendix tables (dimensions formula against computed, verdict matrix) in reports/tables.{md,tex}
tables: venv
	$(BIN)/stiefelsym tables --report-dir reports

## flows: integrated flows, work-precision diagrams and Lax spectra along trajectories in reports/flows/
flows: venv
	$(BIN)/stiefelsym flows --report-dir reports/flows

## speed: residual and time against n and precision, the cost model and its fit, in reports/speed/ (the
## cost model's series go to 20 s per run: about 30 minutes)
speed: venv
	$(BIN)/stiefelsym speed --report-dir reports/speed --model-file stiefelsym/methods/costmodel.json

## costmodel: refit the cost model from its stored measurements (byte for byte: the same fit, plots and tables)
.PHONY: costmodel
costmodel: venv
	$(BIN)/stiefelsym speed --cost-only --records stiefelsym/methods/costmodel.json --report-dir reports/speed \
		--model-file stiefelsym/methods/costmodel.json

## check: re-trace every record of reports/results.json, compare the graph digests, re-derive and
## re-check every dimension-free certificate (a hand-edited or stale results file fails)
.PHONY: check
check: venv
	$(BIN)/stiefelsym check reports/results.json

## report: re-render reports/verification.{md,tex} from reports/results.json
report: venv
	$(BIN)/stiefelsym report --results reports/results.json

#: the paper's LaTeX source (for its equation and theorem numbers)
PAPER ?= ../shared/paper/fedorov-jovanovic-stiefel.tex

## paper-labels: the paper's printed numbers of its labels (proofs/paper_labels.json), by compiling it
paper-labels: venv
	$(BIN)/python -c "import sys; from pathlib import Path; from stiefelsym import paperref; \
	print(len(paperref.write(Path(sys.argv[1]), Path('proofs/paper_labels.json'))), 'labels')" $(PAPER)

## docs: docs/index.md from README.md, and the site (mkdocs build --strict) in site/
.PHONY: docs
docs: venv
	sed -e 's#(docs/\([a-z]*\.md\))#(\1)#g' README.md > docs/index.md
	$(BIN)/mkdocs build --strict -d site

## clean: remove build artefacts and caches (not .venv, not reports/)
clean:
	rm -rf build *.egg-info .pytest_cache
	find . -name __pycache__ -type d -not -path './$(VENV)/*' -prune -exec rm -rf {} +
	rm -f reports/*.aux reports/*.log reports/*.out reports/*.toc reports/*.pdf
