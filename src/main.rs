//! The `gen-rapid` command: parse the command line, run, print the error chain once, and turn
//! the result into an exit status. All work happens in the library (`gen_rapid::cli`).

use clap::{Args, CommandFactory, Parser, Subcommand, ValueEnum};
use gen_rapid::cli::compare::{compare, CompareOptions};
use gen_rapid::cli::locate::{locate, LocateOptions};
use gen_rapid::cli::outputs;
use gen_rapid::cli::robots::{list, RobotsOptions};
use gen_rapid::cli::run::{run, RunOptions};
use gen_rapid::error::{Error, Failure};
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
  gen-rapid cells/torch-trunk.yaml --template templates/arc-weld.mod.j2 --set seam=seam1 --set weld=weld1
                                                  seams as ArcLStart/ArcL/ArcLEnd
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
a point. With a tool block, leave out motion.tool. docs/cell.md describes every key.

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
    /// (templates/module.mod.j2 is the default; docs/outputs.md lists the names a template may use).
    #[arg(long, value_name = "FILE")]
    template: Option<PathBuf>,
    /// A template setting the template reads as settings.NAME (repeatable; with --template),
    /// e.g. --set seam=seam1 --set weld=weld1 for templates/arc-weld.mod.j2.
    #[arg(long = "set", value_name = "NAME=VALUE", requires = "template", value_parser = gen_rapid::output::rapid::parse_setting)]
    settings: Vec<(String, String)>,
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
/// (the cell, the template), or the file stdout goes to while stdout takes the module or the
/// report: one would overwrite the other (`--svg out --report out`, `--svg d/../a.svg --report
/// ./a.svg`, `-o cell.yaml`, `locate cell.yaml --svg cell.yaml`, `--svg /dev/stdout` with the
/// module on stdout). Outputs are compared by what they will be (`cli::same_file`: resolved
/// links and `..`, existing or not). The robot's URDF and controller file, named in the cell,
/// are checked once it is read (`cli::write_for`). Then an output that cannot be written
/// whatever the run makes (a directory, a missing directory) fails before any work (exit 4).
fn check_outputs(
    inputs: &[(&'static str, Option<&Path>)],
    outputs: &[(&'static str, Option<&Path>)],
    stdout_used: bool,
) -> Result<(), ExitCode> {
    let named = |list: &[(&'static str, Option<&Path>)]| -> Vec<(&'static str, PathBuf)> {
        list.iter()
            .filter_map(|(flag, p)| p.map(|p| (*flag, p.to_path_buf())))
            .collect()
    };
    let (inputs, outputs) = (named(inputs), named(outputs));
    let usage = |message: String| {
        let e = Cli::command().error(clap::error::ErrorKind::ArgumentConflict, message);
        // clap prints to stderr and ignores a failed write; the status says it all then.
        let _ = e.print();
        ExitCode::from(gen_rapid::error::exit::USAGE)
    };
    // An input read from the pipe or file the run writes to (`--template /dev/stdout`) would
    // wait on itself for ever, or read what it writes.
    for (flag, path) in &inputs {
        if gen_rapid::cli::is_stdout(path) || gen_rapid::cli::is_stderr(path) {
            return Err(usage(format!(
                "{flag} {} names the file stdout or stderr goes to, which the run writes; give it a file to read",
                path.display()
            )));
        }
    }
    for (i, (flag, path)) in outputs.iter().enumerate() {
        let clash = outputs[..i]
            .iter()
            .chain(inputs.iter())
            .find(|(_, other)| gen_rapid::cli::same_file(path, other));
        if let Some((other, _)) = clash {
            return Err(usage(format!(
                "{flag} {} names the same file as {other}; give each output its own file, apart from the files read",
                path.display()
            )));
        }
        if stdout_used && gen_rapid::cli::is_stdout(path) {
            return Err(usage(format!(
                "{flag} {} names the file stdout goes to, which takes the module (or the report); give it another file, or write the module with -o FILE",
                path.display()
            )));
        }
    }
    for (_, path) in &outputs {
        if let Some(e) = gen_rapid::cli::unwritable(path) {
            return Err(report(&Failure {
                error: Box::new(e),
                file: String::new(),
                text: None,
                notes: Vec::new(),
            }));
        }
    }
    Ok(())
}

/// Prints a failure to stderr (never panicking: a failed write leaves the status to say it) and
/// returns its exit status.
fn report(failure: &Failure) -> ExitCode {
    gen_rapid::cli::outputs::say(&failure.render());
    ExitCode::from(failure.error.exit_code())
}

/// Whether stdout was closed when the process started (`>&-`), which the Rust runtime then
/// opens on `/dev/null` before `main` (so a write "succeeds" and the module is lost): recorded
/// before the runtime starts, by [`STDOUT_CLOSED_AT_START`]. Linux only (`/proc`); elsewhere
/// `false`.
static STDOUT_CLOSED: std::sync::atomic::AtomicBool = std::sync::atomic::AtomicBool::new(false);

/// Runs before `main` and before the Rust runtime's own start, as the C runtime's constructors
/// do: notes whether file descriptor 1 is open (`/proc/self/fd/1` names it when it is).
#[cfg(target_os = "linux")]
#[used]
#[link_section = ".init_array"]
static STDOUT_CLOSED_AT_START: extern "C" fn() = {
    extern "C" fn note() {
        if std::fs::symlink_metadata("/proc/self").is_ok()
            && std::fs::read_link("/proc/self/fd/1").is_err()
        {
            STDOUT_CLOSED.store(true, std::sync::atomic::Ordering::SeqCst);
        }
    }
    note
};

/// The command line, or the exit status of a command line that is not one to run: `--help` and
/// `--version` printed (exit 4 when stdout cannot take them), a usage error printed to stderr
/// (exit 2; a failed write there leaves the status to say it).
fn parse() -> Result<Cli, ExitCode> {
    use clap::error::ErrorKind;
    use std::io::{IsTerminal, Write};
    match Cli::try_parse() {
        Ok(cli) => Ok(cli),
        Err(e) if matches!(e.kind(), ErrorKind::DisplayHelp | ErrorKind::DisplayVersion) => {
            let text = if std::io::stdout().is_terminal() {
                e.render().ansi().to_string()
            } else {
                e.render().to_string()
            };
            let mut out = std::io::stdout().lock();
            match out.write_all(text.as_bytes()).and_then(|_| out.flush()) {
                Ok(()) if !STDOUT_CLOSED.load(std::sync::atomic::Ordering::SeqCst) => {
                    Err(ExitCode::SUCCESS)
                }
                _ => Err(ExitCode::from(gen_rapid::error::exit::OUTPUT)),
            }
        }
        Err(e) => {
            let _ = e.print();
            Err(ExitCode::from(e.exit_code().clamp(0, 255) as u8))
        }
    }
}

fn main() -> ExitCode {
    let cli = match parse() {
        Ok(cli) => cli,
        Err(status) => return status,
    };
    // Where stdout takes the command's result: the module without -o, compare's table and
    // locate's report always.
    let stdout_used = match &cli.command {
        None => cli.run.output.is_none(),
        Some(_) => true,
    };
    let checked = match &cli.command {
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
                stdout_used,
            )
        }
        Some(Command::Compare(a)) => check_outputs(
            &[("CELL", Some(&a.cell))],
            &[("--svg", a.svg.as_deref())],
            stdout_used,
        ),
        Some(Command::Locate(a)) => check_outputs(
            &[("CELL", Some(&a.cell))],
            &[("--svg", a.svg.as_deref())],
            stdout_used,
        ),
        Some(Command::Robots(_)) => Ok(()),
    };
    if let Err(status) = checked {
        return status;
    }
    if stdout_used && STDOUT_CLOSED.load(std::sync::atomic::Ordering::SeqCst) {
        return report(&Failure {
            error: Box::new(Error::Write {
                path: "<stdout>".into(),
                source: std::io::Error::other(
                    "stdout is closed, so the result would go nowhere; give it a file (`> FILE`) or write the module with -o FILE",
                ),
            }),
            file: String::new(),
            text: None,
            notes: Vec::new(),
        });
    }
    let quiet = cli.command.is_none() && cli.run.quiet;
    // A setting given twice is a command-line error (exit 2), before any work.
    let settings = match gen_rapid::output::rapid::settings_map(&cli.run.settings) {
        Ok(map) => map,
        Err(message) => {
            let _ = Cli::command()
                .error(clap::error::ErrorKind::ArgumentConflict, message)
                .print();
            return ExitCode::from(gen_rapid::error::exit::USAGE);
        }
    };
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
            settings,
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
    // What the command made goes out now (cli::outputs: stdout, the summary line, the files).
    match result {
        Ok(summary) => {
            let line = (!quiet).then_some(summary.as_str());
            match outputs::commit(line, false) {
                Ok(()) => ExitCode::SUCCESS,
                Err(e) => report(&Failure {
                    error: Box::new(e),
                    file: String::new(),
                    text: None,
                    notes: Vec::new(),
                }),
            }
        }
        Err(failure) => {
            // The pictures of a failure and compare's table are committed; a failure to do so
            // is not said over the failure itself (one error a run).
            let _ = outputs::commit(None, true);
            report(&failure)
        }
    }
}
