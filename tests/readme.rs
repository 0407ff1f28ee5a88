//! The README's examples still do what the README says (trap class 9 of issue 24): every
//! `$ racket-impact ...` line of its console blocks runs (exit 0, no error), and where the
//! README shows the output, the command prints exactly that (up to a `...` line, which marks
//! the rest as left out). A `$ cat FILE` line shows a file shipped in the repository: its text
//! must be the file's.

mod common;

/// One example: the command after `$ `, and the output lines shown under it.
struct Example {
    command: String,
    shown: Vec<String>,
}

fn examples(readme: &str) -> Vec<Example> {
    let mut out: Vec<Example> = Vec::new();
    let mut in_console = false;
    for line in readme.lines() {
        if line.starts_with("```") {
            in_console = line.trim() == "```console";
            continue;
        }
        if !in_console {
            continue;
        }
        match line.strip_prefix("$ ") {
            Some(cmd) => out.push(Example { command: cmd.to_string(), shown: Vec::new() }),
            None => {
                if let Some(last) = out.last_mut() {
                    last.shown.push(line.to_string());
                }
            }
        }
    }
    out
}

#[test]
fn every_readme_example_runs_and_prints_what_the_readme_shows() {
    let readme = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/README.md")).unwrap();
    let dir = tempfile::tempdir().unwrap();
    let all = examples(&readme);
    assert!(all.len() >= 8, "{} examples found", all.len());
    let mut failures = Vec::new();
    for ex in &all {
        // the command without its trailing `# comment`
        let command = ex.command.split(" #").next().unwrap().trim();
        let words: Vec<&str> = command.split_whitespace().collect();
        if words[0] == "cat" {
            // a file the README shows is shipped with it, as shown (a newcomer runs the
            // examples on it), and is copied where the examples run
            let shipped = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join(words[1]);
            let text = std::fs::read_to_string(&shipped).unwrap_or_else(|e| panic!("{}: {e}", shipped.display()));
            if text != ex.shown.join("\n") + "\n" {
                failures.push(format!("{command}: {} is not what the README shows", words[1]));
            }
            let copy = dir.path().join(words[1]);
            std::fs::create_dir_all(copy.parent().unwrap()).unwrap();
            std::fs::write(copy, text).unwrap();
            continue;
        }
        assert_eq!(words[0], "racket-impact", "{command}");
        let o = common::bin().current_dir(dir.path()).args(&words[1..]).output().unwrap();
        let stderr = String::from_utf8_lossy(&o.stderr);
        if !o.status.success() || stderr.contains("error") {
            failures.push(format!("{command}: exit {:?}: {stderr}", o.status.code()));
            continue;
        }
        let printed: Vec<String> =
            String::from_utf8_lossy(&o.stdout).lines().map(|l| l.trim_end().to_string()).collect();
        let shown: Vec<String> =
            ex.shown.iter().take_while(|l| l.trim() != "...").map(|l| l.trim_end().to_string()).collect();
        let complete = shown.len() == ex.shown.len();
        let matches = if complete { printed == shown } else { printed.starts_with(&shown) };
        if !shown.is_empty() && !matches {
            failures.push(format!("{command}:\nREADME:\n{}\nprinted:\n{}", shown.join("\n"), printed.join("\n")));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n\n"));
}

/// `uncertainty --claims`, README and REPORT.md tell the same counts of verdicts (the command
/// once counted no borderline verdict where the report, which checks every verdict again at
/// twice the samples, counted one).
#[test]
fn the_claims_counts_agree_in_the_command_readme_and_report() {
    let root = env!("CARGO_MANIFEST_DIR");
    let o = common::bin().args(["uncertainty", "--claims", "--format", "json"]).output().unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let json: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let count = |group: &str, verdict: &str| -> u64 {
        json[group][verdict].as_u64().unwrap_or_else(|| panic!("{group}.{verdict} in {}", json[group]))
    };
    let claims = json["outputs"].as_object().unwrap().len() as u64;
    let c = |v| count("conclusion_verdicts", v);
    let n = |v| count("verdicts", v);
    // the README's prose, a count of none written as a word
    let readme = std::fs::read_to_string(format!("{root}/README.md")).unwrap();
    let readme = readme.split_whitespace().collect::<Vec<_>>().join(" ");
    let number = |k: u64, one: &str, many: &str| match k {
        0 => format!("none {one}"),
        1 => format!("1 {one}"),
        _ => format!("{k} {many}"),
    };
    let phrases = [
        format!("{} of the {claims} hold in every sample", c("holds")),
        format!("{} mostly", c("mostly")),
        format!("{} are contested", c("contested")),
        number(c("fails"), "fails", "fail"),
        number(c("independent"), "does not depend on the sampled inputs", "do not depend on the sampled inputs"),
        format!("{} hold by construction", c("by_construction")),
        format!("{} hold over the whole 5-95 % interval", n("holds")),
        format!("{} over part of it", n("part")),
        format!("{} nowhere", n("not at all")),
        number(
            n("independent"),
            "does not depend on the sampled inputs (verdict `independent`)",
            "do not depend on the sampled inputs (verdict `independent`)",
        ),
        number(n("no number"), "states no number", "state no number"),
        number(n("borderline"), "is borderline", "are borderline"),
    ];
    let missing: Vec<&String> = phrases.iter().filter(|p| !readme.contains(p.as_str())).collect();
    assert!(missing.is_empty(), "README does not say what `uncertainty --claims` counts: {missing:?}");
    // REPORT.md's two count lines give the same numbers, in this order
    let report = std::fs::read_to_string(format!("{root}/REPORT.md")).unwrap();
    let numbers_in = |start: &str| -> Vec<u64> {
        let line = report.lines().find(|l| l.starts_with(start)).unwrap_or_else(|| panic!("{start}"));
        let bold = line.split("**").nth(1).unwrap();
        bold.split(|ch: char| !ch.is_ascii_digit()).filter(|w| !w.is_empty()).map(|w| w.parse().unwrap()).collect()
    };
    let conclusions: Vec<u64> =
        ["holds", "mostly", "contested", "fails", "independent", "borderline", "by_construction"].map(c).to_vec();
    assert_eq!(numbers_in("**Conclusions:"), conclusions, "REPORT.md's conclusions against the command's");
    let numbers: Vec<u64> = ["holds", "part", "not at all", "independent", "no number", "borderline"].map(n).to_vec();
    assert_eq!(numbers_in("**Numbers:"), numbers, "REPORT.md's numbers against the command's");
}

/// The counts README's "What it reproduces" gives are REPORT.md's headline counts (README said
/// "32 of 44" for an hour after REPORT.md had moved on to 39 of 52).
#[test]
fn readme_counts_are_the_reports() {
    let root = env!("CARGO_MANIFEST_DIR");
    let read = |f: &str| std::fs::read_to_string(format!("{root}/{f}")).unwrap();
    let words = |s: &str| s.split_whitespace().collect::<Vec<_>>().join(" ");
    // the number just before a phrase
    fn number_before(text: &str, phrase: &str) -> Option<u32> {
        let at = text.find(phrase)?;
        text[..at].split_whitespace().last()?.trim_matches(|c: char| !c.is_ascii_digit()).parse().ok()
    }
    let report = words(&read("REPORT.md"));
    let headline =
        report.split("**").find(|s| s.contains("claims on the model reproduced")).expect("REPORT.md's headline");
    let readme = words(&read("README.md"));
    let section = &readme[readme.find("## What it reproduces").expect("README's section")..];
    for (what, report_phrase, readme_phrase) in [
        ("reproduced", " of the ", " of the "),
        ("claims on the model", " claims on the model", " claims on the model"),
        ("also converged", " of them also converged", " of them also with converged"),
        ("differ", " differ", " misses"),
    ] {
        let ours = number_before(headline, report_phrase);
        let theirs = number_before(section, readme_phrase);
        assert!(ours.is_some(), "REPORT.md's headline gives no count for '{what}': {headline}");
        assert_eq!(theirs, ours, "README's count for '{what}' is not REPORT.md's: {headline}");
    }
}

/// The numbers README's "Model variants" quotes are what the commands it gives beside them print
/// (README quoted the rigid frame's 0.3903 / 0.3907 and the hand's 0.4238 -> 0.4244 without
/// saying they need `--load node`, and the default load prints others): each bullet's
/// `racket-impact sweep ...` is run, and every e_A it prints, to four decimals, is in the bullet.
#[test]
fn the_variants_numbers_are_what_the_commands_beside_them_print() {
    let readme = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/README.md")).unwrap();
    let section = readme.split("## Model variants").nth(1).unwrap().split("\n## ").next().unwrap();
    // the bullets, each joined into one line
    let bullets: Vec<String> = section
        .split("\n- ")
        .skip(1)
        .map(|b| b.split("\n\n").next().unwrap().split_whitespace().collect::<Vec<_>>().join(" "))
        .collect();
    let mut checked = 0;
    for bullet in &bullets {
        for command in bullet.split('`').skip(1).step_by(2).filter(|c| c.starts_with("racket-impact sweep ")) {
            let o = common::bin().args(command.split_whitespace().skip(1)).output().unwrap();
            assert!(o.status.success(), "{command}: {}", String::from_utf8_lossy(&o.stderr));
            let csv = String::from_utf8(o.stdout).unwrap();
            let mut lines = csv.lines();
            let column = lines.next().unwrap().split(',').position(|c| c == "e_a").expect("an e_a column");
            for row in lines {
                let e_a: f64 = row.split(',').nth(column).unwrap().parse().unwrap();
                let shown = format!("{e_a:.4}");
                assert!(bullet.contains(&shown), "{command} prints e_A {shown}, which README does not say:\n{bullet}");
                checked += 1;
            }
        }
    }
    assert!(checked >= 4, "only {checked} numbers checked");
}
