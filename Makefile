# racket-impact: one command per job. `make figures` regenerates every result of the paper,
# `make test` runs every test (what CI runs).
CARGO ?= cargo
BIN := target/release/racket-impact

.PHONY: all build test figures report golden bench fmt lint clean

all: build

build:
	$(CARGO) build --release --locked

# Doc examples first, then the whole suite under nextest, whose summary is the last line.
test:
	$(CARGO) test --locked --doc
	$(CARGO) nextest run --locked --no-fail-fast

figures: build
	$(BIN) figures --out figures
	$(BIN) report

report: build
	$(BIN) report

# Deliberately re-bless the golden snapshots (review `git diff golden/` afterwards).
golden:
	INSTA_UPDATE=always CI= $(CARGO) nextest run --locked --no-fail-fast

bench:
	$(CARGO) bench --locked

fmt:
	$(CARGO) fmt --all

lint:
	$(CARGO) fmt --all -- --check
	$(CARGO) clippy --locked --all-targets -- -D warnings

clean:
	$(CARGO) clean
