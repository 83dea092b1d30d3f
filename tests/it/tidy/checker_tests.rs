//! The tidy rules' checkers on small made-up crates: each rule finds the violation planted in
//! its input and nothing in the same input without it.

use super::scan::{parse, Crate, Source};
use super::{
    direction_violations, file_cycles, issue_numbers, long_files, missing_docs, stated_order,
    unlisted_modules,
};

/// A crate of the given files (`lib.rs` first).
fn krate(files: &[(&str, &str)]) -> Crate {
    let sources: Vec<Source> = files.iter().map(|(p, t)| Source::new(p, t)).collect();
    parse(&sources, "lib.rs").expect("the made-up crate parses")
}

const LIB: &str = "//! Root.\npub mod early;\npub mod late;\npub mod leaf;\n";
const ORDER: &[&str] = &["early", "late"];
const LEAVES: &[&str] = &["leaf"];

#[test]
fn direction_finds_a_stage_using_one_to_its_right_or_a_leaf_using_a_stage() {
    let lawful = [
        ("lib.rs", LIB),
        (
            "early/mod.rs",
            "//! E.\nmod part;\nuse crate::leaf::Tool;\npub struct E;\n\
             #[cfg(test)]\nmod tests { use crate::late::L; }\n",
        ),
        // Test code and a test file may use anything.
        (
            "early/part.rs",
            "//! P.\npub fn f() -> super::E { super::E }\n#[cfg(test)]\nmod more;\n\
             #[cfg(test)]\nfn g() { crate::late::h(); }\n",
        ),
        ("early/part/more.rs", "//! M.\nuse crate::late::L;\n"),
        (
            "late.rs",
            "//! L.\nuse crate::early;\npub struct L;\npub fn h() { early::part::f(); }\n",
        ),
        ("leaf.rs", "//! T.\npub struct Tool;\n"),
    ];
    let k = krate(&lawful);
    assert_eq!(
        direction_violations(&k, ORDER, LEAVES),
        Vec::<String>::new()
    );
    assert_eq!(unlisted_modules(&k, ORDER, LEAVES), Vec::<String>::new());
    // Each of these, alone, breaks the order.
    for (file, text, written) in [
        (
            "leaf.rs",
            "//! T.\nuse crate::early::E;\n",
            "crate::early::E",
        ),
        (
            "early/part.rs",
            "//! P.\npub fn f() { let _ = crate::late::L; }\n",
            "crate::late::L",
        ),
        (
            "early/part.rs",
            "//! P.\npub fn f() { println!(\"{:?}\", super::super::late::h()); }\n",
            "super::super::late::h",
        ),
        (
            "early/mod.rs",
            "//! E.\nmod part;\npub mod inner { use super::super::late; }\n",
            "super::super::late",
        ),
    ] {
        let files: Vec<(&str, &str)> = lawful
            .iter()
            .map(|&(p, t)| if p == file { (p, text) } else { (p, t) })
            .collect();
        let found = direction_violations(&krate(&files), ORDER, LEAVES);
        assert_eq!(found.len(), 1, "{file}: {found:?}");
        assert!(found[0].contains(written), "{found:?}");
    }
    // A module in neither list, and a listed name that is no module.
    let k = krate(&[
        ("lib.rs", "//! R.\npub mod early;\npub mod stray;\n"),
        ("early.rs", "//! E.\n"),
        ("stray.rs", "//! S.\n"),
    ]);
    let found = unlisted_modules(&k, ORDER, LEAVES);
    assert!(found.iter().any(|f| f.contains("`stray`")), "{found:?}");
    assert!(found.iter().any(|f| f.contains("`late`")), "{found:?}");
}

#[test]
fn cycles_are_found_between_siblings_but_not_with_their_module_file() {
    let files = |b_text: &'static str| {
        vec![
            ("lib.rs", "//! R.\nmod m;\n"),
            (
                "m/mod.rs",
                "//! M.\nmod a;\nmod b;\npub use a::A;\npub struct Core;\n",
            ),
            (
                "m/a.rs",
                "//! A.\nuse super::b::B;\nuse super::Core;\npub struct A;\n",
            ),
            ("m/b.rs", b_text),
        ]
    };
    let lawful = krate(&files("//! B.\nuse super::Core;\npub struct B;\n"));
    assert_eq!(file_cycles(&lawful), Vec::<Vec<String>>::new());
    let cyclic = krate(&files("//! B.\npub struct B(super::a::A);\n"));
    assert_eq!(
        file_cycles(&cyclic),
        vec![vec!["m/a.rs".to_string(), "m/b.rs".to_string()]]
    );
    // A cycle through test code only is none.
    let tested = krate(&files(
        "//! B.\npub struct B;\n#[cfg(test)]\nmod t { use super::super::a::A; }\n",
    ));
    assert_eq!(file_cycles(&tested), Vec::<Vec<String>>::new());
}

#[test]
fn long_files_must_say_why_and_short_ones_must_not_claim_to_be_long() {
    let body = "fn f() {}\n".repeat(799);
    let at_limit = Source::new("a.rs", &format!("//! A.\n{body}"));
    let over = Source::new("b.rs", &format!("//! B.\n{body}\n"));
    let said = Source::new("c.rs", &format!("//! C (long: one table).\n{body}\n"));
    let said_later = Source::new("d.rs", &format!("//! D.\n//! (long: one table).\n{body}\n"));
    let stale = Source::new("e.rs", &format!("//! E (long: one table).\n{body}"));
    let found = long_files(&[at_limit, over, said, said_later, stale], 800);
    assert_eq!(found.len(), 3, "{found:?}");
    assert!(found[0].starts_with("src/b.rs: 801 lines"), "{found:?}");
    assert!(found[1].starts_with("src/d.rs: 802 lines"), "{found:?}");
    assert!(
        found[2].starts_with("src/e.rs: 800 lines, within"),
        "{found:?}"
    );
}

#[test]
fn issue_numbers_are_found_in_their_usual_spellings_only() {
    let text = "//! Doc.\n\
                // the refine stage (issue 10)\n\
                /// Issues 8 and 9\n\
                // see issue #12\n\
                // fixed in #3.\n\
                let c = \"#505050\"; // a colour\n\
                // tissue 3, r#\"raw\"#, [#4a]\n\
                // an issue, 2 of them\n";
    let found = issue_numbers(&[Source::new("x.rs", text)]);
    let lines: Vec<&str> = found
        .iter()
        .map(|f| f.split(": ").next().unwrap_or(""))
        .collect();
    assert_eq!(
        lines,
        ["src/x.rs:2", "src/x.rs:3", "src/x.rs:4", "src/x.rs:5"]
    );
}

#[test]
fn every_file_must_open_with_a_module_doc() {
    let found = missing_docs(&[
        Source::new("a.rs", "//! A.\nfn f() {}\n"),
        Source::new("b.rs", "\n\n//! B.\n"),
        Source::new("c.rs", "use std::fmt;\n//! C.\n"),
        Source::new("d.rs", "/// An item doc is no module doc.\nfn f() {}\n"),
        Source::new("e.rs", ""),
    ]);
    assert_eq!(
        found,
        [
            "src/c.rs: does not open with a `//!` doc",
            "src/d.rs: does not open with a `//!` doc",
            "src/e.rs: does not open with a `//!` doc",
        ]
    );
}

#[test]
fn the_stated_order_is_read_from_the_dependency_paragraph() {
    let doc = "# A\n\nThe `x` module.\n\nDependency direction: `a` → `b` →\n`c`. A module uses \
               the modules to its left and the leaves (`l1`,\n`l2`), which use nothing; \
               the `z` trait aside.\n";
    let (order, leaves) = stated_order(doc).expect("stated");
    assert_eq!(
        (order, leaves),
        (
            vec!["a".into(), "b".into(), "c".into()],
            vec!["l1".into(), "l2".into()]
        )
    );
    assert_eq!(stated_order("No such paragraph."), None);
}
