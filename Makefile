# racket-impact: one command per job. `make figures` regenerates every result of the paper,
# `make test` runs every test (what CI runs).
CARGO ?= cargo
BIN := target/release/racket-impact

.PHONY: all build test figures report golden bench fmt lint fuzz clean

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

# The string-face maps (CSV + PNG + JSON each; tests/map.rs checks the committed ones against
# these lines).
figures: build
	$(BIN) figures --out figures
	$(BIN) map --racket paper-125hz --load node --quantity power --out figures/map_paper_power.csv
	$(BIN) map --racket tweener --quantity power --out figures/map_tweener_power.csv
	$(BIN) map --racket tweener --quantity power --compare-tension-lb 50,60 --out figures/map_tweener_50_vs_60lb.csv
	$(BIN) report

report: build
	$(BIN) report

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

fmt:
	$(CARGO) fmt --all

lint:
	$(CARGO) fmt --all -- --check
	$(CARGO) clippy --locked -p racket-impact -p racket-impact-bench --all-targets -- -D warnings
	RUSTDOCFLAGS="-D warnings" $(CARGO) doc --locked --no-deps

clean:
	$(CARGO) clean
