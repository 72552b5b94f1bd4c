// ok-det: benchmark command; wall-clock timing and f64 results are reported, never simulated.
//! `fixstep bench accuracy`, `stability` and `cloth`: run a benchmark, write its files
//! into the output directory atomically, print its tables.

use std::io::Write;
use std::path::Path;
use std::time::Instant;

use super::args::BenchCommand;
use super::output::{print_line, write_error};
use super::output_file::OutputFile;
use super::progress::Progress;
use super::status::Status;
use fixstep::particles::Integrator;
use fixstep_bench::{
    AccuracyConfig, StabilityConfig, accuracy_csv, floors_table, measured_orders, orders_table,
    run_accuracy_with_progress, run_stability_with_progress, stability_csv, stability_table,
    work_precision_svg,
};

/// Runs the benchmark `command` names.
pub fn bench(command: &BenchCommand) -> Result<Status, String> {
    match command {
        BenchCommand::Accuracy { out, quick } => accuracy(out, *quick),
        BenchCommand::Stability { out } => stability(out),
        BenchCommand::Cloth => cloth(),
    }
}

/// The accuracy sweep: `accuracy.csv`, `work-precision.svg`, the orders and floors tables.
fn accuracy(out: &Path, quick: bool) -> Result<Status, String> {
    output_directory(out)?;
    // Open the outputs first, so a bad directory fails before the run rather than after it.
    let csv = open(&out.join("accuracy.csv"))?;
    let svg = open(&out.join("work-precision.svg"))?;
    let config = if quick {
        AccuracyConfig::quick()
    } else {
        AccuracyConfig::full()
    };
    let started = Instant::now(); // ok-det: wall time is reported, never simulated
    let mut progress = Progress::runs(config.points());
    let rows = run_accuracy_with_progress(&config, |done| progress.update(done as u64));
    progress.finish();
    let wall = started.elapsed().as_secs_f64();
    let orders = measured_orders(&rows);
    commit(csv, accuracy_csv(&rows).as_bytes())?;
    commit(svg, work_precision_svg(&rows)?.as_bytes())?;
    for line in orders_table(&orders)
        .into_iter()
        .chain([String::new()])
        .chain(floors_table(&rows))
    {
        print_line(&line)?;
    }
    print_line(&format!(
        "accuracy: {} runs ({} halvings, fastest of {}) in {wall:.1} s; wrote {} and {}",
        rows.len(),
        config.halvings,
        config.repeats,
        out.join("accuracy.csv").display(),
        out.join("work-precision.svg").display()
    ))?;
    Ok(Status::Ok)
}

/// The stability sweep: `stability.csv` and its table.
fn stability(out: &Path) -> Result<Status, String> {
    output_directory(out)?;
    let csv = open(&out.join("stability.csv"))?;
    let started = Instant::now(); // ok-det: wall time is reported, never simulated
    let config = StabilityConfig::full();
    let mut progress = Progress::runs(config.limits());
    let rows = run_stability_with_progress(&config, |done| progress.update(done as u64));
    progress.finish();
    let wall = started.elapsed().as_secs_f64();
    commit(csv, stability_csv(&rows).as_bytes())?;
    for line in stability_table(&rows) {
        print_line(&line)?;
    }
    print_line(&format!(
        "stability: {} limits in {wall:.1} s; wrote {}",
        rows.len(),
        out.join("stability.csv").display()
    ))?;
    Ok(Status::Ok)
}

/// The cloth trade: implicit against semi-implicit Euler at their largest stable steps.
fn cloth() -> Result<Status, String> {
    let rows =
        fixstep_bench::run_cloth(&[Integrator::SemiImplicitEuler, Integrator::ImplicitEuler]);
    for line in fixstep_bench::cloth_table(&rows) {
        print_line(&line)?;
    }
    Ok(Status::Ok)
}

/// Makes sure `dir` is a directory, creating it (and its parents) if missing.
fn output_directory(dir: &Path) -> Result<(), String> {
    if dir.exists() && !dir.is_dir() {
        return Err(format!("{}: --out is not a directory", dir.display()));
    }
    std::fs::create_dir_all(dir)
        .map_err(|e| format!("{}: cannot create the output directory: {e}", dir.display()))
}

/// Starts the output file `path`.
fn open(path: &Path) -> Result<OutputFile, String> {
    OutputFile::create(path)
}

/// Writes `bytes` to `file` and puts it in place.
fn commit(mut file: OutputFile, bytes: &[u8]) -> Result<(), String> {
    file.write_all(bytes)
        .map_err(|e| write_error(file.path(), &e))?;
    file.commit()
}
