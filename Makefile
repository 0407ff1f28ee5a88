# racket-impact: one command per job. `make figures` regenerates every result of the paper,
# `make test` runs every test (what CI runs).
CARGO ?= cargo
BIN := target/release/racket-impact

.PHONY: all build test python-test python-stub figures report golden bench fmt lint fuzz clean

all: build

build:
	$(CARGO) build --release --locked

# Doc examples first, then the whole suite, both built with the release profile: `make figures`
# has built the library and every dependency with it, so the tests compile only themselves
# (Cargo.toml declares the features the test-only crates turn on, so nothing is rebuilt for
# them; the benchmarks' criterion is a package of its own). The runner is cargo-nextest where it
# is installed (one process per test, and its summary is the last line; `.ci/run` installs it),
# else plain `cargo test`, so that a machine with only the Rust toolchain needs no third command
# (the suite passes under either; tests/makefile.rs checks that the fallback is chosen without
# nextest on PATH). Expected time on a 2-core machine after `make figures`: README "Set up".
ifeq ($(shell $(CARGO) nextest --version >/dev/null 2>&1 && echo yes),yes)
SUITE := $(CARGO) nextest run --locked --release --no-fail-fast
else
SUITE := $(CARGO) test --locked --release --no-fail-fast --lib --bins --tests
endif

test:
	$(CARGO) test --locked --release --doc
	$(SUITE)
	@$(MAKE) --no-print-directory python-test

# The Python package (python/): `pip install ./python` builds it with maturin in this target
# directory (reusing the release build's compiled library), here into target/python, and pytest
# runs its suite against the command line. The tests need Python 3.9+ with maturin, pytest,
# numpy and pandas: python/tools.sh finds them in $(PYTHON), or installs them once from the
# package registry into target/venv, and fails with one line when it cannot; without Python 3.9+
# the step says in one line that the Python tests need it (and fails under CI).
PYTHON ?= python3
PYTHON_VENV ?= $(CURDIR)/target/venv
# The Python with the tools (empty: no Python here, already said), and the package built into
# target/python with it (its build backend runs the `maturin` program of that Python's scripts
# folder).
PYTHON_WITH_TOOLS = py=$$(sh python/tools.sh "$(PYTHON)" "$(PYTHON_VENV)") || exit 1
PYTHON_PACKAGE = PATH="$$("$$py" -c 'import sysconfig; print(sysconfig.get_path("scripts"))'):$$PATH" \
	"$$py" -m pip install --quiet --disable-pip-version-check --no-build-isolation --no-deps --upgrade \
	--target target/python ./python

python-test: build
	@$(PYTHON_WITH_TOOLS); [ -n "$$py" ] || exit 0; \
	$(PYTHON_PACKAGE) && \
	PYTHONPATH=$(CURDIR)/target/python RACKET_IMPACT_BIN=$(BIN) "$$py" -m pytest -q -p no:cacheprovider python/tests

# Regenerate the Python package's type stub from the parameters' declaration (the tests fail
# while it is stale).
python-stub: build
	@$(PYTHON_WITH_TOOLS); [ -n "$$py" ] || exit 1; \
	$(PYTHON_PACKAGE) && \
	PYTHONPATH=$(CURDIR)/target/python "$$py" -m racket_impact._stub > python/racket_impact/__init__.pyi

# The string-face maps (CSV + PNG + JSON each; tests/map.rs checks the committed ones against
# these lines), then the cards (CSV + PNG; tests/card.rs checks them likewise), built again first:
# a card compiles in figures/validation_spin.csv (what its spin law was validated on), which
# `figures` has just written. The report of this build is kept in target/tmp/cache
# (src/cli/cache.rs), where the tests' runs of the binary find it instead of computing it again.
figures: export RACKET_IMPACT_CACHE := $(CURDIR)/target/tmp/cache
figures: build
	$(BIN) figures --out figures
	$(BIN) map --racket paper-125hz --load node --quantity power --out figures/map_paper_power.csv
	$(BIN) map --racket tweener --quantity power --out figures/map_tweener_power.csv
	$(BIN) map --racket tweener --quantity power --compare-tension-lb 50,60 --out figures/map_tweener_50_vs_60lb.csv
	$(CARGO) build --release --locked
	$(BIN) card --racket tweener --string alu-power-16 --out figures/card_tweener.csv
	$(BIN) card --compare paper-widebody-200hz --out figures/card_paper.csv
	$(BIN) report --summary

report: export RACKET_IMPACT_CACHE := $(CURDIR)/target/tmp/cache
report: build
	$(BIN) report --summary

# Deliberately re-bless: regenerate figures/ and REPORT.md, then rewrite the golden snapshots
# (review `git diff golden/ figures/ REPORT.md` afterwards).
golden: figures
	INSTA_UPDATE=always CI= $(SUITE)

bench:
	$(CARGO) bench --locked -p racket-impact-bench

# Coverage-guided fuzzing of the config parser (needs `cargo install cargo-fuzz`; the stable
# toolchain is allowed nightly flags with RUSTC_BOOTSTRAP). FUZZ_SECONDS bounds the run.
FUZZ_SECONDS ?= 60
fuzz:
	cd fuzz && RUSTC_BOOTSTRAP=1 $(CARGO) fuzz run config -- -max_total_time=$(FUZZ_SECONDS) -max_len=512

# Every source file is named: the registries declare the tangential mechanisms' and the
# experiments' modules from their lists (one line each), and `cargo fmt` alone walks only the
# modules it sees declared.
SOURCES = $(shell find src -name '*.rs')

fmt:
	$(CARGO) fmt --all -- $(SOURCES)

lint:
	$(CARGO) fmt --all -- --check $(SOURCES)
	$(CARGO) clippy --locked -p racket-impact -p racket-impact-bench --all-targets -- -D warnings
	RUSTDOCFLAGS="-D warnings" $(CARGO) doc --locked --no-deps

clean:
	$(CARGO) clean
