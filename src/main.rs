//! The `gen-rapid` command: parse the command line, run, print the error chain once, and turn
//! the result into an exit status. All work happens in the library (`gen_rapid::cli`).

use clap::{Args, CommandFactory, Parser, Subcommand, ValueEnum};
use gen_rapid::cli::compare::{compare, CompareOptions};
use gen_rapid::cli::locate::{locate, LocateOptions};
use gen_rapid::cli::robots::{list, RobotsOptions};
use gen_rapid::cli::run::{run, RunOptions};
use gen_rapid::plan::Method;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

const EXAMPLES: &str = "\
Examples:
  gen-rapid cells/trunk.yaml > trunk.mod          plan the trunk cell, module on stdout
  gen-rapid cells/trunk.yaml -o trunk.mod         the same, written atomically to a file
  gen-rapid cells/trunk.yaml --planner depth-first --grid 2
  gen-rapid cells/trunk.yaml --no-shortcut        the paper's method alone (no shortcut pass)
  gen-rapid cells/trunk.yaml --svg trunk.svg      also draw the route over the C-space
  gen-rapid cells/trunk.yaml --html trunk.html    also a 3D preview page (open it in a browser)
  gen-rapid cells/trunk.yaml --report trunk.json  also the results as JSON
  gen-rapid cells/trunk.yaml --template templates/module-local.mod.j2 --proc Weld
                                                  your own module template, routine Weld
  gen-rapid compare cells/trunk.yaml --svg all.svg      the three methods side by side
  gen-rapid locate cells/trunk-auto.yaml --svg r.svg    where the base may stand (region R)
  gen-rapid robots                                      the robots built in (robot.model)

A minimal cell (mm and degrees; joint values are the controller's, as in a jointtarget):
  module: Demo
  robot: { urdf: ../robots/irb1400.urdf, base: [0, 0, 0] }   # path relative to this file
  obstacles:
    - { name: table, box: { min: [600, -300, 0], max: [1000, 300, 400] } }
  points:
    - { name: P1, joints: [-30, 0, 0] }
    - { name: P2, joints: [30, 0, 0] }
Optional: robot.yaw, robot.wrist, robot.controller (a controller file for the URDF), points as
xyz (wrist centre), base: auto, planner.method (extensile), planner.grid (1 deg),
planner.clearance (10 mm), planner.shortcut (true), motion.speed/zone/tool/proc (v300, fine,
tool0, main), motion.via_zone (fine; e.g. z50: a via flies by where its corner is proven).

A tool, a work object and points as TCP poses (robtargets; quaternions [w, x, y, z]):
  tool:                                  # the tooldata to declare, with its collision volumes
    name: tTorch
    tframe: [[0, 0, 350], [0.9238795, 0, 0.3826834, 0]]   # TCP in the flange frame (mm, quat)
    mass: 2.5                            # kg, default 1; cog: [x, y, z] mm, default [0, 0, 0]
    shapes:                              # flange frame; end them short of the TCP
      - { name: neck, cylinder: { from: [0, 0, 0], to: [0, 0, 300], radius: 25 } }
      - { name: body, box: { min: [-45, -45, 0], max: [45, 45, 110] } }
      - { name: cup, sphere: { centre: [0, 0, 320], radius: 15 } }
  wobj: { name: wobjDoor, uframe: [[400, 0, 500], [1, 0, 0, 0]] }   # user frame in the cell
  points:
    - { name: W1, robtarget: [[600, -100, 300], [0, 0, 1, 0]] }     # TCP pose in the wobj
    - { name: W2, robtarget: [[600, 100, 300], [0, 0, 1, 0], [0, -1, 0, 0]], speed: v100 }
A robtarget point may give its confdata [cf1, cf4, cf6, cfx]; speed and zone set the move into
a point. With a tool block, leave out motion.tool. README.md describes every key.

The module goes to stdout (or -o FILE); one summary line goes to stderr. On error nothing is
written to stdout and no module FILE is made; when planning fails, --svg FILE draws why (the
blocked nodes, the points of the failed leg ringed; locate: the reach circles) and --html FILE
shows the cell and the points that could not be joined.

Exit status: 0 success, 1 invalid cell, robot files or template, 2 bad command line, 3 planning
failed (point unreachable or in collision, no path), 4 the module could not be written.";

/// Plans a collision-free joint-space path through a robot cell's points and writes it as an
/// ABB RAPID module of MoveAbsJ moves (method of Ting & Jar 2006).
#[derive(Parser)]
#[command(name = "gen-rapid", version, after_help = EXAMPLES, args_conflicts_with_subcommands = true, subcommand_negates_reqs = true)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
    #[command(flatten)]
    run: RunArgs,
}

#[derive(Args)]
struct RunArgs {
    /// The cell file (YAML).
    #[arg(required = true, value_name = "CELL")]
    cell: Option<PathBuf>,
    /// Write the module to FILE (atomically) instead of stdout.
    #[arg(short, long, value_name = "FILE")]
    output: Option<PathBuf>,
    /// Path search, overriding the cell's planner.method.
    #[arg(long, value_enum, value_name = "METHOD")]
    planner: Option<MethodArg>,
    /// Grid spacing d in degrees, overriding the cell's planner.grid (0.25 .. 10).
    #[arg(long, value_name = "DEG", value_parser = parse_grid)]
    grid: Option<f64>,
    /// Also draw the route over the blocked nodes of the configuration space to FILE (SVG); when
    /// planning fails, the blocked nodes with the points of the failed leg ringed.
    #[arg(long, value_name = "FILE")]
    svg: Option<PathBuf>,
    /// Also write a 3D preview page to FILE: one self-contained HTML file (the cell, the arm
    /// and tool moving along the estimated timing, the smallest clearance); when planning fails,
    /// a page of the points that could not be joined.
    #[arg(long, value_name = "FILE")]
    html: Option<PathBuf>,
    /// Also write the run's results as JSON to FILE (waypoints, moves with their clearance,
    /// time, speed and zone; docs/report.schema.json).
    #[arg(long, value_name = "FILE")]
    report: Option<PathBuf>,
    /// Render the module through this minijinja template instead of the embedded one
    /// (templates/module.mod.j2 is the default; README lists the names a template may use).
    #[arg(long, value_name = "FILE")]
    template: Option<PathBuf>,
    /// Name the routine that makes the moves (default: the cell's motion.proc, else main).
    #[arg(long = "proc", value_name = "NAME")]
    proc_name: Option<String>,
    /// Print no summary line and no progress bar on stderr (warnings and errors still appear).
    /// Without it, a run that lasts over a second shows a progress bar while stderr is a
    /// terminal (never when stderr is a pipe or a file).
    #[arg(short, long)]
    quiet: bool,
    /// Keep the paper's method alone: no shortcut pass after its shortening and merge (as
    /// planner.shortcut: false). Zones are certified either way.
    #[arg(long)]
    no_shortcut: bool,
}

#[derive(Subcommand)]
enum Command {
    /// Run the three search methods on the same grid and print one table: moves, path
    /// length, manipulation time, planning time (exit 0 if any method succeeds, 3 if none).
    Compare(CompareArgs),
    /// Robot location (paper section 2): the region R of base positions that reach every point
    /// clear of the obstacles, its area and bounding box, and the base with the largest margin.
    /// For a fixed base, also whether that base lies in R.
    Locate(LocateArgs),
    /// The robots built into gen-rapid (the names robot.model takes), each with its reach,
    /// coupling, axis ranges and speeds.
    Robots(RobotsArgs),
}

#[derive(Args)]
struct RobotsArgs {
    /// Print the list as JSON on stdout instead of text.
    #[arg(long)]
    json: bool,
}

#[derive(Args)]
struct LocateArgs {
    /// The cell file (YAML).
    #[arg(value_name = "CELL")]
    cell: PathBuf,
    /// Also draw the top view (obstacles, reach circles, R, base) to FILE as SVG (atomically);
    /// also when R is empty.
    #[arg(long, value_name = "FILE")]
    svg: Option<PathBuf>,
    /// Print the report as JSON on stdout instead of text.
    #[arg(long)]
    json: bool,
}

#[derive(Args)]
struct CompareArgs {
    /// The cell file (YAML).
    #[arg(value_name = "CELL")]
    cell: PathBuf,
    /// Print the comparison as JSON instead of a table.
    #[arg(long)]
    json: bool,
    /// Draw every method's route over the configuration space to FILE (SVG); when none finds
    /// one, the points they failed at ringed.
    #[arg(long, value_name = "FILE")]
    svg: Option<PathBuf>,
    /// Grid spacing d in degrees, overriding the cell's planner.grid (0.25 .. 10).
    #[arg(long, value_name = "DEG", value_parser = parse_grid)]
    grid: Option<f64>,
}

#[derive(Clone, Copy, ValueEnum)]
enum MethodArg {
    /// Paper 4.1: 26 neighbours, smallest wave number (saw-tooth paths).
    Neighboring,
    /// Paper 4.2: axis steps only; fails where only a diagonal gets through.
    DepthFirst,
    /// Paper 4.3: both ways, merged, shortened recursively (default).
    Extensile,
}

impl From<MethodArg> for Method {
    fn from(m: MethodArg) -> Method {
        match m {
            MethodArg::Neighboring => Method::Neighboring,
            MethodArg::DepthFirst => Method::DepthFirst,
            MethodArg::Extensile => Method::Extensile,
        }
    }
}

fn parse_grid(s: &str) -> Result<f64, String> {
    let g: f64 = s.parse().map_err(|_| format!("'{s}' is not a number"))?;
    gen_rapid::cell::check_grid(g)
}

/// Refuses (exit 2) a command whose output files name the same file twice, or a file it reads
/// (the cell, the template): one would overwrite the other (`--svg out --report out`,
/// `-o cell.yaml`, `locate cell.yaml --svg cell.yaml`). The robot's URDF and controller file,
/// named in the cell, are checked once it is read (`cli::write_for`).
fn check_outputs(
    inputs: &[(&'static str, Option<&Path>)],
    outputs: &[(&'static str, Option<&Path>)],
) {
    let named = |list: &[(&'static str, Option<&Path>)]| -> Vec<(&'static str, PathBuf)> {
        list.iter()
            .filter_map(|(flag, p)| p.map(|p| (*flag, p.to_path_buf())))
            .collect()
    };
    let (inputs, outputs) = (named(inputs), named(outputs));
    for (i, (flag, path)) in outputs.iter().enumerate() {
        let clash = outputs[..i]
            .iter()
            .chain(inputs.iter())
            .find(|(_, other)| gen_rapid::cli::same_file(path, other));
        if let Some((other, _)) = clash {
            Cli::command()
                .error(
                    clap::error::ErrorKind::ArgumentConflict,
                    format!(
                        "{flag} {} names the same file as {other}; give each output its own file, apart from the files read",
                        path.display()
                    ),
                )
                .exit();
        }
    }
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    match &cli.command {
        None => {
            let a = &cli.run;
            check_outputs(
                &[
                    ("CELL", a.cell.as_deref()),
                    ("--template", a.template.as_deref()),
                ],
                &[
                    ("--output", a.output.as_deref()),
                    ("--svg", a.svg.as_deref()),
                    ("--html", a.html.as_deref()),
                    ("--report", a.report.as_deref()),
                ],
            )
        }
        Some(Command::Compare(a)) => {
            check_outputs(&[("CELL", Some(&a.cell))], &[("--svg", a.svg.as_deref())])
        }
        Some(Command::Locate(a)) => {
            check_outputs(&[("CELL", Some(&a.cell))], &[("--svg", a.svg.as_deref())])
        }
        Some(Command::Robots(_)) => {}
    }
    let quiet = cli.command.is_none() && cli.run.quiet;
    let result = match cli.command {
        None => run(&RunOptions {
            cell: cli.run.cell.unwrap_or_default(),
            output: cli.run.output,
            planner: cli.run.planner.map(Method::from),
            grid_deg: cli.run.grid,
            svg: cli.run.svg,
            html: cli.run.html,
            report: cli.run.report,
            template: cli.run.template,
            proc_name: cli.run.proc_name,
            quiet: cli.run.quiet,
            no_shortcut: cli.run.no_shortcut,
        }),
        Some(Command::Compare(a)) => compare(&CompareOptions {
            cell: a.cell,
            json: a.json,
            svg: a.svg,
            grid_deg: a.grid,
        }),
        Some(Command::Locate(a)) => locate(&LocateOptions {
            cell: a.cell,
            svg: a.svg,
            json: a.json,
        }),
        Some(Command::Robots(a)) => list(&RobotsOptions { json: a.json }),
    };
    match result {
        Ok(summary) => {
            if !quiet {
                eprintln!("{summary}");
            }
            ExitCode::SUCCESS
        }
        Err(failure) => {
            eprint!("{}", failure.render());
            ExitCode::from(failure.error.exit_code())
        }
    }
}
