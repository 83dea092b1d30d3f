//! `--template FILE` and `--proc NAME`: the embedded template is `templates/module.mod.j2`
//! (the flag with it gives the same bytes as no flag), every example template under
//! `templates/` renders a cell into a module that passes the project's RAPID checks (the dense
//! re-check and the TCP check read it as the controller would), a template's error points at
//! its line (exit 1, nothing on stdout), and the routine's name follows the one name rule.

use crate::common::library::load_cell;
use crate::common::{arg, gen_rapid, root, stderr, stdout, temp_cell};

/// The example templates and what each must show.
const EXAMPLES: [&str; 3] = [
    "templates/module.mod.j2",
    "templates/module-prg-header.mod.j2",
    "templates/module-local.mod.j2",
];

#[test]
fn the_default_template_file_gives_the_same_bytes_as_no_flag() {
    for cell in ["cells/trunk.yaml", "cells/torch-trunk.yaml"] {
        let plain = gen_rapid(&[cell]);
        let with = gen_rapid(&[cell, "--template", "templates/module.mod.j2"]);
        assert!(
            plain.status.success() && with.status.success(),
            "{}",
            stderr(&with)
        );
        assert!(!plain.stdout.is_empty());
        assert_eq!(plain.stdout, with.stdout, "{cell}");
    }
}

#[test]
fn every_example_template_renders_a_module_that_passes_the_rapid_checks() {
    let path = root().join("cells/torch-trunk.yaml");
    let cell = load_cell(&path);
    let default = stdout(&gen_rapid(&["cells/torch-trunk.yaml"]));
    for template in EXAMPLES {
        let out = gen_rapid(&[
            "cells/torch-trunk.yaml",
            "--template",
            template,
            "--proc",
            "WeldTrunk",
        ]);
        assert!(out.status.success(), "{template}: {}", stderr(&out));
        let text = stdout(&out);
        // The module runs as the controller runs it: its process moves too.
        crate::common::process::check_process(&cell, &text, template)
            .unwrap_or_else(|f| panic!("{template}:\n{}", f.join("\n")));
        let m = crate::common::module::Module::parse(&text).expect("the module");
        assert_eq!(m.proc_name, "WeldTrunk", "{template}");
        assert_eq!(m.robtargets.len(), 4, "{template}: the seam robtargets");
        // The same data and instructions as the default module, only the form differs.
        let plain = crate::common::module::Module::parse(&default).expect("the default module");
        let declarations = plain.targets.len() + plain.robtargets.len();
        assert_eq!(m.targets, plain.targets, "{template}");
        assert_eq!(m.robtargets, plain.robtargets, "{template}");
        let ins = |m: &crate::common::module::Module| -> Vec<_> {
            m.body.iter().map(|s| s.ins.clone()).collect()
        };
        assert_eq!(ins(&m), ins(&plain), "{template}");
        match template {
            "templates/module-prg-header.mod.j2" => {
                assert_eq!(m.program_header, ["VERSION:1", "LANGUAGE:ENGLISH"]);
                assert!(text.starts_with(
                    "%%%\n  VERSION:1\n  LANGUAGE:ENGLISH\n%%%\n\nMODULE TorchTrunk\n"
                ));
                assert_eq!(m.local, 0);
            }
            "templates/module-local.mod.j2" => {
                assert!(m.program_header.is_empty());
                // Every jointtarget and robtarget, not the tool or the work object.
                assert_eq!(m.local, declarations, "{template}");
                assert!(text.contains("\n    PERS tooldata tTorch := "));
                assert!(text.contains("\n    LOCAL CONST robtarget L1_rt := "));
            }
            _ => {
                assert!(m.program_header.is_empty() && m.local == 0);
                assert_eq!(text, default.replace("PROC main()", "PROC WeldTrunk()"));
            }
        }
    }
}

#[test]
fn a_template_error_points_at_its_line_and_writes_nothing() {
    let dir = tempfile::tempdir().expect("temp dir");
    let out_file = dir.path().join("out.mod");
    // An unknown name (the context is strict): found when rendering, after planning.
    let t = dir.path().join("typo.mod.j2");
    std::fs::write(
        &t,
        "MODULE {{ module }}\n! fine so far\n    PROC {{ procedure }}()\nENDMODULE\n",
    )
    .expect("write");
    let out = gen_rapid(&[
        "cells/trunk.yaml",
        "--template",
        arg(&t),
        "-o",
        arg(&out_file),
    ]);
    assert_eq!(out.status.code(), Some(1), "{}", stderr(&out));
    assert!(out.stdout.is_empty() && !out_file.exists());
    let err = stderr(&out);
    assert!(err.contains(&format!("--> {}:3:", t.display())), "{err}");
    assert!(err.contains("3 |     PROC {{ procedure }}()"), "{err}");
    assert!(err.contains("undefined"), "{err}");
    // A syntax error: found when the template is read, before planning.
    let t = dir.path().join("broken.mod.j2");
    std::fs::write(
        &t,
        "MODULE {{ module }}\n{% for t in targets %}\n    {{ t.name }}\n",
    )
    .expect("write");
    let out = gen_rapid(&["cells/trunk.yaml", "--template", arg(&t)]);
    assert_eq!(out.status.code(), Some(1), "{}", stderr(&out));
    assert!(out.stdout.is_empty());
    let err = stderr(&out);
    assert!(
        err.contains(&format!("--> {}:", t.display())) && err.contains("syntax error"),
        "{err}"
    );
    // No file at all.
    let out = gen_rapid(&[
        "cells/trunk.yaml",
        "--template",
        arg(&dir.path().join("none.j2")),
    ]);
    assert_eq!(out.status.code(), Some(1));
    assert!(
        stderr(&out).contains("cannot read template"),
        "{}",
        stderr(&out)
    );
}

#[test]
fn the_routine_is_named_by_the_cell_or_the_command_line_under_the_one_name_rule() {
    let dir = tempfile::tempdir().expect("temp dir");
    let body = "module: Demo\nrobot: { urdf: URDF, base: [0, 0, 0] }\nobstacles: []\npoints:\n  - { name: P1, joints: [-30, 0, 0] }\n  - { name: P2, joints: [30, 0, 0] }\nmotion:\n  proc: Weld\n";
    let cell = temp_cell(dir.path(), "proc.yaml", body);
    let out = gen_rapid(&[arg(&cell)]);
    assert!(out.status.success(), "{}", stderr(&out));
    assert!(stdout(&out).contains("\n    PROC Weld()\n"));
    // --proc overrides motion.proc.
    let out = gen_rapid(&[arg(&cell), "--proc", "Weld2"]);
    assert!(stdout(&out).contains("\n    PROC Weld2()\n") && !stdout(&out).contains("Weld()"));
    // A point may be called main when the routine is not.
    let main_point = body.replace("name: P1", "name: main");
    let cell2 = temp_cell(dir.path(), "main_point.yaml", &main_point);
    assert!(gen_rapid(&[arg(&cell2)]).status.success());
    // ... but not when it is.
    let out = gen_rapid(&[arg(&cell2), "--proc", "main"]);
    assert_eq!(out.status.code(), Some(1));
    assert!(out.stdout.is_empty());
    // --proc clashing with a point, or not a RAPID name: input errors, nothing on stdout.
    for (name, says) in [
        ("p2", "routine name 'p2' is already the name of point 'P2'"),
        (
            "Demo",
            "routine name 'Demo' is already the name of the module",
        ),
        ("PROC", "--proc 'PROC' is not a valid RAPID name"),
        ("v100", "--proc 'v100' is not a valid RAPID name"),
        ("2nd", "--proc '2nd' is not a valid RAPID name"),
    ] {
        let out = gen_rapid(&[arg(&cell), "--proc", name]);
        assert_eq!(out.status.code(), Some(1), "{name}: {}", stderr(&out));
        assert!(out.stdout.is_empty());
        assert!(stderr(&out).contains(says), "{name}: {}", stderr(&out));
    }
}

/// The arc-welding example, `templates/arc-weld.mod.j2`, on the two welding cells: its module
/// passes the strict grammar and runs as the controller runs it (`check_process_welding`: the
/// arc instructions move as the MoveL / MoveC they make, every sample kept clear), writes each
/// seam as `ArcLStart` / `ArcL` / `ArcLEnd` (`ArcC...` for the arc) with the seamdata and
/// welddata given by `--set`, switches the weld where the cell's `SetDO doWeld` stood and writes
/// no `SetDO doWeld` of its own; its targets and the path of every motion are the default
/// module's (the same data, the same instruction kinds and arguments but for the welding data).
#[test]
fn the_arc_weld_template_writes_the_seams_as_arc_instructions_on_the_proven_paths() {
    use crate::common::module::Module;
    use crate::common::routine::Instruction;
    let expected: [(&str, &[&str]); 2] = [
        (
            "cells/torch-trunk.yaml",
            &[
                "ArcLStart L1_rt, v300, seamA, weldA, fine, tTorch\\WObj:=wobjTrunk;",
                "ArcLEnd L2_rt, v50, seamA, weldA, fine, tTorch\\WObj:=wobjTrunk;",
                "ArcLStart R1_rt, v300, seamA, weldA, fine, tTorch\\WObj:=wobjTrunk;",
                "ArcLEnd R2_rt, v50, seamA, weldA, fine, tTorch\\WObj:=wobjTrunk;",
            ],
        ),
        (
            "cells/arc-seam.yaml",
            &[
                "ArcLStart S1_rt, v300, seamA, weldA, fine, tTorch\\WObj:=wobjTrunk;",
                "ArcCEnd S2_via, S2_rt, v20, seamA, weldA, fine, tTorch\\WObj:=wobjTrunk;",
            ],
        ),
    ];
    for (cell_file, arcs) in expected {
        let cell = load_cell(&root().join(cell_file));
        let out = gen_rapid(&[
            cell_file,
            "--template",
            "templates/arc-weld.mod.j2",
            "--set",
            "seam=seamA",
            "--set",
            "weld=weldA",
        ]);
        assert!(out.status.success(), "{cell_file}: {}", stderr(&out));
        let text = stdout(&out);
        let run =
            crate::common::process::check_process_welding(&cell, &text, cell_file, Some("doWeld"))
                .unwrap_or_else(|f| panic!("{cell_file}:\n{}", f.join("\n")));
        assert!(run.process_moves >= 3, "{cell_file}: {run:?}");
        let m = Module::parse(&text).expect("the module");
        let written: Vec<&str> = m
            .body
            .iter()
            .filter(|s| s.text.starts_with("Arc"))
            .map(|s| s.text.as_str())
            .collect();
        assert_eq!(written, arcs, "{cell_file}");
        assert!(
            !text.contains("SetDO doWeld"),
            "{cell_file}: a SetDO doWeld is left"
        );
        assert!(text.contains("! arc welding: seams as ArcLStart/ArcL/ArcLEnd, seamdata seamA, welddata weldA, switched by doWeld\n"));
        // The same data and the same motions as the default module, the welding data aside.
        let plain = Module::parse(&stdout(&gen_rapid(&[cell_file]))).expect("the default module");
        assert_eq!(m.targets, plain.targets, "{cell_file}");
        assert_eq!(m.robtargets, plain.robtargets, "{cell_file}");
        let motions = |m: &Module| -> Vec<_> {
            m.motions()
                .map(|(_, mo)| {
                    let mut mo = mo.clone();
                    mo.arc = None;
                    mo
                })
                .collect()
        };
        assert_eq!(motions(&m), motions(&plain), "{cell_file}");
        // The other actions as the default module writes them.
        let others = |m: &Module| -> Vec<String> {
            (m.body.iter())
                .filter(|s| matches!(s.ins, Instruction::Action(_)))
                .map(|s| s.text.clone())
                .filter(|t| !t.starts_with("SetDO doWeld"))
                .collect()
        };
        assert_eq!(others(&m), others(&plain), "{cell_file}");
    }
}

/// Template settings: `--set NAME=VALUE` reaches the template as `settings.NAME`; a setting the
/// template needs and the command line does not give is an error at the template's line (exit
/// 1); a malformed one, one given twice, or `--set` without `--template` is a command-line
/// error (exit 2); nothing reaches stdout.
#[test]
fn template_settings_come_from_the_command_line_and_are_checked() {
    let dir = tempfile::tempdir().expect("temp dir");
    let t = dir.path().join("settings.mod.j2");
    std::fs::write(
        &t,
        "MODULE {{ module }}\n    ! site: {{ settings.site }}, cell {{ settings.cell | default(\"none\") }}\nENDMODULE\n",
    )
    .expect("write");
    let out = gen_rapid(&[
        "cells/trunk.yaml",
        "--template",
        arg(&t),
        "--set",
        "site=Plant 7",
    ]);
    assert!(out.status.success(), "{}", stderr(&out));
    assert_eq!(
        stdout(&out),
        "MODULE TrunkWeld\n    ! site: Plant 7, cell none\nENDMODULE\n"
    );
    // Not given: the template's line.
    let out = gen_rapid(&["cells/trunk.yaml", "--template", arg(&t)]);
    assert_eq!(out.status.code(), Some(1), "{}", stderr(&out));
    assert!(out.stdout.is_empty());
    assert!(
        stderr(&out).contains(&format!("--> {}:2:", t.display())),
        "{}",
        stderr(&out)
    );
    // The command line's errors.
    for (args, says) in [
        (vec!["--set", "site"], "is not NAME=VALUE"),
        (vec!["--set", "2site=a"], "is not a setting name"),
        (
            vec!["--set", "site=a", "--set", "site=b"],
            "--set site is given more than once",
        ),
    ] {
        let mut all = vec!["cells/trunk.yaml", "--template", arg(&t)];
        all.extend(args);
        let out = gen_rapid(&all);
        assert_eq!(out.status.code(), Some(2), "{all:?}: {}", stderr(&out));
        assert!(out.stdout.is_empty());
        assert!(stderr(&out).contains(says), "{all:?}: {}", stderr(&out));
    }
    let out = gen_rapid(&["cells/trunk.yaml", "--set", "site=a"]);
    assert_eq!(out.status.code(), Some(2), "{}", stderr(&out));
    assert!(stderr(&out).contains("--template"), "{}", stderr(&out));
}
