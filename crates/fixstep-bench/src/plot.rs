// ok-det: benchmark plotting of f64 results; never inside a tick.
//! The work–precision diagram: log₁₀ error against log₁₀ seconds, one panel per problem,
//! one line per integrator × format (colour: integrator; line style: format), drawn with
//! plotters' SVG backend.

use plotters::coord::Shift;
use plotters::prelude::*;

use super::format::NumberFormat;
use super::problems::Problem;
use super::sweep::AccuracyRow;
use fixstep::particles::Integrator;

/// Width and height of the figure, px.
const SIZE: (u32, u32) = (1500, 1000);

/// One colour per integrator, in [`Integrator::ALL`] order.
const COLOURS: [RGBColor; Integrator::ALL.len()] = [
    RGBColor(214, 39, 40),
    RGBColor(255, 127, 14),
    RGBColor(44, 160, 44),
    RGBColor(31, 119, 180),
    RGBColor(148, 103, 189),
    RGBColor(23, 190, 207),
    RGBColor(140, 86, 75),
];

/// The SVG document of the work–precision diagram of `rows`. Points with an infinite or
/// zero error are left out.
pub fn work_precision_svg(rows: &[AccuracyRow]) -> Result<String, String> {
    let mut svg = String::new();
    draw(
        rows,
        SVGBackend::with_string(&mut svg, SIZE).into_drawing_area(),
    )
    .map_err(|e| format!("cannot draw the work-precision diagram: {e}"))?;
    Ok(svg)
}

type Area<'a> = DrawingArea<SVGBackend<'a>, Shift>;
type DrawResult = Result<(), DrawingAreaErrorKind<std::io::Error>>;

fn draw(rows: &[AccuracyRow], root: Area<'_>) -> DrawResult {
    root.fill(&WHITE)?;
    let root = root.titled(
        "work-precision: log10 error vs log10 seconds (fastest run)",
        ("sans-serif", 24),
    )?;
    let mut problems: Vec<Problem> = rows.iter().map(|row| row.problem).collect();
    problems.dedup();
    let panels = root.split_evenly((2, 3));
    for (&problem, panel) in problems.iter().zip(&panels) {
        draw_panel(panel, problem, rows)?;
    }
    if let Some(legend) = panels.get(problems.len()) {
        draw_legend(legend)?;
    }
    root.present()
}

/// The (log₁₀ seconds, log₁₀ error) points of one line.
fn line_points(
    rows: &[AccuracyRow],
    problem: Problem,
    integrator: Integrator,
    format: NumberFormat,
) -> Vec<(f64, f64)> {
    rows.iter()
        .filter(|r| (r.problem, r.integrator, r.format) == (problem, integrator, format))
        .filter(|r| r.error.is_finite() && r.error > 0.0 && r.seconds > 0.0)
        .map(|r| (r.seconds.log10(), r.error.log10()))
        .collect()
}

/// One line of a panel: an integrator in a format.
struct Line {
    integrator: Integrator,
    format: NumberFormat,
    points: Vec<(f64, f64)>,
}

fn draw_panel(panel: &Area<'_>, problem: Problem, rows: &[AccuracyRow]) -> DrawResult {
    let lines: Vec<Line> = Integrator::ALL
        .iter()
        .flat_map(|&integrator| {
            NumberFormat::ALL.iter().map(move |&format| {
                let points = line_points(rows, problem, integrator, format);
                Line {
                    integrator,
                    format,
                    points,
                }
            })
        })
        .filter(|line| !line.points.is_empty())
        .collect();
    let all = lines.iter().flat_map(|line| line.points.iter());
    let (mut x_min, mut x_max, mut y_min, mut y_max) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
    for &(x, y) in all {
        (x_min, x_max) = (x_min.min(x), x_max.max(x));
        (y_min, y_max) = (y_min.min(y), y_max.max(y));
    }
    if x_min > x_max {
        (x_min, x_max, y_min, y_max) = (-6.0, 0.0, -12.0, 0.0);
    }
    let mut chart = ChartBuilder::on(panel)
        .caption(problem.title(), ("sans-serif", 18))
        .margin(10)
        .x_label_area_size(35)
        .y_label_area_size(45)
        .build_cartesian_2d(
            (x_min - 0.2)..(x_max + 0.2),
            (y_min - 0.5).floor()..(y_max + 0.5).ceil(),
        )?;
    chart
        .configure_mesh()
        .x_desc("log10 seconds")
        .y_desc("log10 error")
        .draw()?;
    for Line {
        integrator,
        format,
        points,
    } in lines
    {
        let colour = COLOURS[integrator as usize];
        match format {
            NumberFormat::F64 => {
                chart.draw_series(LineSeries::new(points, colour.stroke_width(1)).point_size(2))?;
            }
            NumberFormat::I32F32 => {
                chart.draw_series(LineSeries::new(points, colour.stroke_width(3)))?;
            }
            NumberFormat::I40F24 => {
                chart.draw_series(DashedLineSeries::new(points, 8, 5, colour.stroke_width(2)))?;
            }
            NumberFormat::I48F16 => {
                chart.draw_series(DashedLineSeries::new(points, 2, 4, colour.stroke_width(2)))?;
            }
        }
    }
    Ok(())
}

/// The key: integrator colours, then format line styles.
fn draw_legend(area: &Area<'_>) -> DrawResult {
    let font = ("sans-serif", 18).into_font();
    area.draw(&Text::new("integrator (colour)", (30, 30), font.clone()))?;
    for (i, integrator) in Integrator::ALL.iter().enumerate() {
        let y = 60 + 26 * i as i32;
        area.draw(&PathElement::new(
            vec![(30, y), (90, y)],
            COLOURS[i].stroke_width(3),
        ))?;
        area.draw(&Text::new(integrator.name(), (100, y - 9), font.clone()))?;
    }
    area.draw(&Text::new("format (line)", (30, 240), font.clone()))?;
    for (i, format) in NumberFormat::ALL.iter().enumerate() {
        let y = 270 + 26 * i as i32;
        let dashes: &[(i32, i32)] = match format {
            NumberFormat::F64 | NumberFormat::I32F32 => &[(30, 90)],
            NumberFormat::I40F24 => &[(30, 38), (43, 51), (56, 64), (69, 77), (82, 90)],
            NumberFormat::I48F16 => &[(30, 32), (36, 38), (42, 44), (48, 50), (54, 56), (60, 62)],
        };
        let width = match format {
            NumberFormat::F64 => 1,
            NumberFormat::I32F32 => 3,
            _ => 2,
        };
        for &(x0, x1) in dashes {
            area.draw(&PathElement::new(
                vec![(x0, y), (x1, y)],
                BLACK.stroke_width(width),
            ))?;
        }
        let label = match format {
            NumberFormat::F64 => "f64 (thin, dots at points)",
            NumberFormat::I32F32 => "I32F32 (thick)",
            NumberFormat::I40F24 => "I40F24 (dashed)",
            NumberFormat::I48F16 => "I48F16 (dotted)",
        };
        area.draw(&Text::new(label, (100, y - 9), font.clone()))?;
    }
    Ok(())
}
