//! `lie-sim plot`: an SVG of a trajectory CSV written by `lie-sim run` — relative energy error
//! (with forces, the energy balance E − E₀ − W), Casimir error, the momentum components and the
//! attitude against time — and the drawing of the work-precision plot for `lie-sim trade`.

use crate::error::SimError;
use crate::output::AtomicFile;
use plotters::prelude::*;
use std::path::Path;

/// A trajectory read back from CSV: the header and one vector per column.
#[derive(Debug, Clone, PartialEq)]
pub struct Trajectory {
    /// Column names.
    pub header: Vec<String>,
    /// Column values, `columns[j][i]` = row i of column j.
    pub columns: Vec<Vec<f64>>,
}

impl Trajectory {
    /// The column named `name`.
    pub fn column(&self, name: &str) -> Option<&[f64]> {
        self.header
            .iter()
            .position(|h| h == name)
            .map(|j| self.columns[j].as_slice())
    }

    /// Number of rows.
    pub fn rows(&self) -> usize {
        self.columns.first().map_or(0, Vec::len)
    }

    /// The momentum columns `mu1 … muN`, in order.
    pub fn momentum(&self) -> Vec<(&str, &[f64])> {
        self.header
            .iter()
            .zip(&self.columns)
            .filter(|(h, _)| h.starts_with("mu") && h[2..].parse::<usize>().is_ok())
            .map(|(h, c)| (h.as_str(), c.as_slice()))
            .collect()
    }
}

/// Reads a CSV written by `lie-sim run`: a header with at least `t` and `energy`, then rows of
/// numbers of the header's length.
pub fn read_csv(path: &Path) -> Result<Trajectory, SimError> {
    let text = crate::input::read_text(path)?;
    parse_csv(&text, &path.display().to_string())
}

/// Parses CSV text (see [`read_csv`]); `label` names it in errors.
pub fn parse_csv(text: &str, label: &str) -> Result<Trajectory, SimError> {
    let bad = |line: usize, message: String| SimError::Csv {
        path: label.into(),
        line,
        message,
    };
    let mut lines = text.lines();
    let header: Vec<String> = lines
        .next()
        .ok_or_else(|| bad(1, "empty file: expected a header".into()))?
        .split(',')
        .map(|s| s.trim().to_string())
        .collect();
    for needed in ["t", "energy"] {
        if !header.iter().any(|h| h == needed) {
            return Err(bad(
                1,
                format!("header has no `{needed}` column (is this a `lie-sim run` CSV?)"),
            ));
        }
    }
    let mut columns = vec![Vec::new(); header.len()];
    for (i, line) in lines.enumerate() {
        if line.trim().is_empty() {
            continue;
        }
        let fields: Vec<&str> = line.split(',').collect();
        if fields.len() != header.len() {
            return Err(bad(
                i + 2,
                format!("{} fields, the header has {}", fields.len(), header.len()),
            ));
        }
        for (j, f) in fields.iter().enumerate() {
            let v: f64 = f
                .trim()
                .parse()
                .map_err(|_| bad(i + 2, format!("`{}`: `{f}` is not a number", header[j])))?;
            columns[j].push(v);
        }
    }
    if columns[0].is_empty() {
        return Err(bad(2, "no data rows".into()));
    }
    Ok(Trajectory { header, columns })
}

/// Signed relative deviation (x − x₀)/|x₀| of a series from its first value (absolute when
/// x₀ = 0).
pub fn relative_deviation(x: &[f64]) -> Vec<f64> {
    let x0 = x.first().copied().unwrap_or(0.0);
    let scale = if x0 == 0.0 { 1.0 } else { x0.abs() };
    x.iter().map(|v| (v - x0) / scale).collect()
}

fn plot_error(path: &Path, e: impl std::fmt::Display) -> SimError {
    SimError::Plot {
        path: path.to_path_buf(),
        message: e.to_string(),
    }
}

/// A y range that contains every finite value, padded by 5 % (or by a small absolute amount when
/// the series is constant, so that the chart is never degenerate).
fn y_range<'a>(series: impl IntoIterator<Item = &'a [f64]>) -> (f64, f64) {
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for s in series {
        for &v in s.iter().filter(|v| v.is_finite()) {
            lo = lo.min(v);
            hi = hi.max(v);
        }
    }
    if !lo.is_finite() {
        return (-1.0, 1.0);
    }
    let span = hi - lo;
    let pad = if span > 0.0 {
        0.05 * span
    } else {
        1e-16f64.max(lo.abs() * 1e-3)
    };
    (lo - pad, hi + pad)
}

fn color(i: usize) -> RGBColor {
    const COLORS: [RGBColor; 10] = [
        RGBColor(31, 119, 180),
        RGBColor(255, 127, 14),
        RGBColor(44, 160, 44),
        RGBColor(214, 39, 40),
        RGBColor(148, 103, 189),
        RGBColor(140, 86, 75),
        RGBColor(227, 119, 194),
        RGBColor(127, 127, 127),
        RGBColor(188, 189, 34),
        RGBColor(23, 190, 207),
    ];
    COLORS[i % COLORS.len()]
}

/// One panel of the trajectory plot: `series` against `t`.
fn panel<DB: DrawingBackend>(
    area: &DrawingArea<DB, plotters::coord::Shift>,
    caption: &str,
    t: &[f64],
    series: &[(&str, Vec<f64>)],
) -> Result<(), String> {
    let (t0, t1) = (t[0], *t.last().unwrap_or(&t[0]));
    let t1 = if t1 > t0 { t1 } else { t0 + 1.0 };
    let (y0, y1) = y_range(series.iter().map(|(_, s)| s.as_slice()));
    let mut chart = ChartBuilder::on(area)
        .caption(caption, ("sans-serif", 18))
        .margin(10)
        .margin_right(30)
        .x_label_area_size(30)
        .y_label_area_size(80)
        .build_cartesian_2d(t0..t1, y0..y1)
        .map_err(|e| e.to_string())?;
    chart
        .configure_mesh()
        .x_desc("t")
        .y_label_formatter(&|v| format!("{v:.2e}"))
        .draw()
        .map_err(|e| e.to_string())?;
    for (i, (name, s)) in series.iter().enumerate() {
        let c = color(i);
        chart
            .draw_series(LineSeries::new(
                t.iter().copied().zip(s.iter().copied()),
                c.stroke_width(2),
            ))
            .map_err(|e| e.to_string())?
            .label(*name)
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], c.stroke_width(2)));
    }
    if series.len() > 1 {
        chart
            .configure_series_labels()
            .border_style(BLACK)
            .background_style(WHITE.mix(0.8))
            .draw()
            .map_err(|e| e.to_string())?;
    }
    Ok(())
}

/// A panel: its caption and its named series.
type Panel<'a> = (String, Vec<(&'a str, Vec<f64>)>);

/// The energy balance `(E − E₀ − W)/max|E|` of a run with forces (its `work` column W; absolute
/// when the energy stays 0): the part of the energy's change the forces' work does not explain.
pub fn energy_balance(energy: &[f64], work: &[f64]) -> Vec<f64> {
    let e0 = energy.first().copied().unwrap_or(0.0);
    let scale = energy.iter().fold(0.0f64, |m, e| m.max(e.abs()));
    let scale = if scale > 0.0 { scale } else { 1.0 };
    energy
        .iter()
        .zip(work)
        .map(|(e, w)| (e - e0 - w) / scale)
        .collect()
}

/// The attitude panels' series: for each body (`qw` or `qw_k` …), its rotation angle
/// θ = |φ| = |(rv1, rv2, rv3)| and, for a single body, its quaternion components.
fn attitude_series(traj: &Trajectory) -> Vec<(String, Vec<f64>)> {
    let suffixes: Vec<String> = traj
        .header
        .iter()
        .filter_map(|h| h.strip_prefix("qw"))
        .map(str::to_string)
        .collect();
    let mut series = Vec::new();
    for sfx in &suffixes {
        let rv: Vec<&[f64]> = (1..=3)
            .filter_map(|i| traj.column(&format!("rv{i}{sfx}")))
            .collect();
        if rv.len() == 3 {
            let angle = (0..traj.rows())
                .map(|r| rv.iter().map(|c| c[r] * c[r]).sum::<f64>().sqrt())
                .collect();
            series.push((format!("θ{sfx} (rad)"), angle));
        }
    }
    if suffixes == [""] {
        for q in ["qw", "qx", "qy", "qz"] {
            if let Some(c) = traj.column(q) {
                series.push((q.to_string(), c.to_vec()));
            }
        }
    }
    series
}

/// Draws the trajectory plot to `out` (atomically), each panel against t: the relative energy
/// error (E − E₀)/|E₀| — or, for a run with forces (a `work` column), the energy balance error
/// (E − E₀ − W)/max|E| ([`energy_balance`]) —, the relative Casimir error (C − C₀)/|C₀| when the
/// CSV has a `casimir` column, μ₁ … μ_N, and the attitude when the CSV has one
/// ([`crate::attitude`]): the rotation angle θ = |φ| of each body and, for one body, its unit
/// quaternion (qw ≥ 0).
pub fn plot_trajectory(traj: &Trajectory, out: &Path, title: &str) -> Result<(), SimError> {
    let t = traj.column("t").unwrap_or(&[]);
    let energy = traj.column("energy").unwrap_or(&[]);
    let mut panels: Vec<Panel> = vec![match traj.column("work") {
        Some(w) => (
            format!("{title}: energy balance error (E − E₀ − W)/max|E|, W the forces' work"),
            vec![("E − E₀ − W", energy_balance(energy, w))],
        ),
        None => (
            format!("{title}: relative energy error (E − E₀)/|E₀|"),
            vec![("energy", relative_deviation(energy))],
        ),
    }];
    if let Some(c) = traj.column("casimir") {
        panels.push((
            "relative Casimir error (C − C₀)/|C₀|".into(),
            vec![("casimir", relative_deviation(c))],
        ));
    }
    let mu: Vec<(&str, Vec<f64>)> = traj
        .momentum()
        .into_iter()
        .map(|(n, c)| (n, c.to_vec()))
        .collect();
    panels.push(("body momentum μ".into(), mu));
    let attitude = attitude_series(traj);
    if !attitude.is_empty() {
        let quaternion = attitude.iter().any(|(n, _)| n == "qw");
        panels.push((
            format!(
                "attitude: rotation angle θ = |φ|{}",
                if quaternion {
                    " and unit quaternion (qw ≥ 0)"
                } else {
                    " of each body"
                }
            ),
            attitude
                .iter()
                .map(|(n, s)| (n.as_str(), s.clone()))
                .collect(),
        ));
    }

    let file = AtomicFile::new(out)?;
    {
        let root = SVGBackend::new(file.temp_path(), (1000, 300 * panels.len() as u32))
            .into_drawing_area();
        root.fill(&WHITE).map_err(|e| plot_error(out, e))?;
        let areas = root.split_evenly((panels.len(), 1));
        for (area, (caption, series)) in areas.iter().zip(&panels) {
            panel(area, caption, t, series).map_err(|e| plot_error(out, e))?;
        }
        root.present().map_err(|e| plot_error(out, e))?;
    }
    file.commit()
}

/// The marker drawn at each point of a series.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Marker {
    /// ●
    Circle,
    /// ▲
    Triangle,
    /// ■
    Square,
    /// ◆
    Diamond,
    /// ×
    Cross,
    /// + (bold when filled)
    Plus,
}

/// How a series is drawn: its colour, a dashed or solid line, its marker, filled or hollow.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SeriesStyle {
    /// Line and marker colour.
    pub color: RGBColor,
    /// Dashed (else solid) line.
    pub dashed: bool,
    /// The marker.
    pub marker: Marker,
    /// Filled (else hollow) marker.
    pub filled: bool,
}

/// One curve of a log–log plot.
pub struct Curve {
    /// Legend label.
    pub label: String,
    /// How it is drawn.
    pub style: SeriesStyle,
    /// Points (x, y), both positive.
    pub points: Vec<(f64, f64)>,
}

/// What is drawn besides the curves: a horizontal line with its legend, points on it, and labelled
/// points.
#[derive(Default)]
pub struct Annotations {
    /// A horizontal line at y (e.g. the reference's floor) and its label.
    pub hline: Option<(f64, String)>,
    /// x of the points drawn as grey ▽ on the horizontal line (runs whose value is below it and
    /// therefore not known: the errors below the reference's floor).
    pub below: Vec<f64>,
    /// Points (x, y) to ring and label.
    pub labels: Vec<(f64, f64, String)>,
}

/// Binds `$mk` to a maker of the marker of `$style` at a position p (pixel offsets around it)
/// and evaluates `$body`: one arm per marker shape, as each shape is its own element type.
macro_rules! with_marker {
    ($style:expr, |$mk:ident| $body:expr) => {{
        let st = $style;
        let shape = if st.filled {
            st.color.filled()
        } else {
            st.color.stroke_width(1)
        };
        match st.marker {
            Marker::Circle => {
                let $mk = |p| EmptyElement::at(p) + Circle::new((0, 0), 4, shape);
                $body
            }
            Marker::Triangle => {
                let $mk = |p| EmptyElement::at(p) + TriangleMarker::new((0, 0), 5, shape);
                $body
            }
            Marker::Square => {
                let $mk = |p| EmptyElement::at(p) + Rectangle::new([(-3, -3), (3, 3)], shape);
                $body
            }
            Marker::Diamond if st.filled => {
                let $mk = |p| {
                    EmptyElement::at(p)
                        + Polygon::new(vec![(0, -5), (5, 0), (0, 5), (-5, 0)], shape)
                };
                $body
            }
            Marker::Diamond => {
                let $mk = |p| {
                    EmptyElement::at(p)
                        + PathElement::new(vec![(0, -5), (5, 0), (0, 5), (-5, 0), (0, -5)], shape)
                };
                $body
            }
            Marker::Cross => {
                let $mk = |p| EmptyElement::at(p) + Cross::new((0, 0), 4, st.color.stroke_width(2));
                $body
            }
            Marker::Plus => {
                let width = if st.filled { 3 } else { 1 };
                let $mk = |p| {
                    EmptyElement::at(p)
                        + PathElement::new(
                            vec![(-5, 0), (5, 0), (0, 0), (0, -5), (0, 5)],
                            st.color.stroke_width(width),
                        )
                };
                $body
            }
        }
    }};
}

/// Draws curves on log–log axes to `out` (atomically), with the legend (line and marker of each
/// curve) beside the chart and the `annotations`; points with a non-positive or non-finite
/// coordinate are left out (they have no place on log axes).
pub fn plot_loglog(
    curves: &[Curve],
    annotations: &Annotations,
    out: &Path,
    title: &str,
    x_desc: &str,
    y_desc: &str,
) -> Result<(), SimError> {
    let ok = |&(x, y): &(f64, f64)| x.is_finite() && y.is_finite() && x > 0.0 && y > 0.0;
    let floor = annotations
        .hline
        .as_ref()
        .map(|(y, _)| *y)
        .filter(|y| y.is_finite() && *y > 0.0);
    // The curves' points and the ▽ marks on the floor (which widen the x range only).
    let all: Vec<(f64, f64)> = curves
        .iter()
        .flat_map(|c| c.points.iter().copied())
        .chain(
            floor
                .into_iter()
                .flat_map(|y| annotations.below.iter().map(move |&x| (x, y))),
        )
        .filter(ok)
        .collect();
    let bounds = |f: fn(&(f64, f64)) -> f64, extra: Option<f64>| {
        let lo = all.iter().map(f).chain(extra).fold(f64::INFINITY, f64::min);
        let hi = all
            .iter()
            .map(f)
            .chain(extra)
            .fold(f64::NEG_INFINITY, f64::max);
        if lo.is_finite() {
            (lo / 2.0, hi * 2.0)
        } else {
            (1e-3, 1.0)
        }
    };
    let (x0, x1) = bounds(|p| p.0, None);
    let (y0, y1) = bounds(|p| p.1, floor);
    let height = 750.max(80 + 20 * (curves.len() as u32 + 1));

    let file = AtomicFile::new(out)?;
    {
        let root = SVGBackend::new(file.temp_path(), (1400, height)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| plot_error(out, e))?;
        let (left, right) = root.split_horizontally(1000);
        let mut chart = ChartBuilder::on(&left)
            .caption(title, ("sans-serif", 20))
            .margin(15)
            .x_label_area_size(40)
            .y_label_area_size(80)
            .build_cartesian_2d((x0..x1).log_scale(), (y0..y1).log_scale())
            .map_err(|e| plot_error(out, e))?;
        chart
            .configure_mesh()
            .x_desc(x_desc)
            .y_desc(y_desc)
            .x_label_formatter(&|v| format!("{v:.0e}"))
            .y_label_formatter(&|v| format!("{v:.0e}"))
            .draw()
            .map_err(|e| plot_error(out, e))?;
        let font = ("sans-serif", 13).into_font().color(&BLACK);
        if let (Some(y), Some((_, label))) = (floor, &annotations.hline) {
            let grey = RGBColor(90, 90, 90);
            chart
                .draw_series(DashedLineSeries::new(
                    [(x0, y), (x1, y)],
                    10,
                    5,
                    grey.stroke_width(2),
                ))
                .map_err(|e| plot_error(out, e))?;
            chart
                .draw_series(std::iter::once(
                    EmptyElement::at((x0, y)) + Text::new(label.clone(), (8, 4), font.clone()),
                ))
                .map_err(|e| plot_error(out, e))?;
            chart
                .draw_series(
                    annotations
                        .below
                        .iter()
                        .filter(|x| x.is_finite() && **x > 0.0)
                        .map(|&x| {
                            EmptyElement::at((x, y))
                                + PathElement::new(
                                    vec![(-5, -4), (5, -4), (0, 5), (-5, -4)],
                                    grey.stroke_width(1),
                                )
                        }),
                )
                .map_err(|e| plot_error(out, e))?;
        }
        for (i, c) in curves.iter().enumerate() {
            let pts: Vec<(f64, f64)> = c.points.iter().copied().filter(ok).collect();
            let st = c.style;
            if st.dashed {
                chart
                    .draw_series(DashedLineSeries::new(
                        pts.clone(),
                        6,
                        4,
                        st.color.stroke_width(2),
                    ))
                    .map_err(|e| plot_error(out, e))?;
            } else {
                chart
                    .draw_series(LineSeries::new(pts.clone(), st.color.stroke_width(2)))
                    .map_err(|e| plot_error(out, e))?;
            }
            with_marker!(st, |mk| chart.draw_series(pts.iter().map(|&p| mk(p))))
                .map_err(|e| plot_error(out, e))?;
            // The legend, drawn by hand in the right-hand strip so that it never hides a curve.
            let y = 50 + 20 * i as i32;
            let sample = vec![(10, y), (50, y)];
            if st.dashed {
                right.draw(&plotters::element::DashedPathElement::new(
                    sample,
                    6,
                    4,
                    st.color.stroke_width(2),
                ))
            } else {
                right.draw(&PathElement::new(sample, st.color.stroke_width(2)))
            }
            .map_err(|e| plot_error(out, e))?;
            with_marker!(st, |mk| right.draw(&mk((30, y)))).map_err(|e| plot_error(out, e))?;
            right
                .draw(&Text::new(c.label.clone(), (58, y - 7), font.clone()))
                .map_err(|e| plot_error(out, e))?;
        }
        for (x, y, label) in &annotations.labels {
            // A value of exactly 0 (an invariant kept exactly, e.g. by the exact flow in one
            // step) has no place on a log axis: its ring and label sit on the axis' bottom.
            let y = if *y == 0.0 { y0 } else { *y };
            if !ok(&(*x, y)) {
                continue;
            }
            chart
                .draw_series(std::iter::once(
                    EmptyElement::at((*x, y))
                        + Circle::new((0, 0), 8, BLACK.stroke_width(1))
                        + Text::new(label.clone(), (10, -16), font.clone()),
                ))
                .map_err(|e| plot_error(out, e))?;
        }
        root.present().map_err(|e| plot_error(out, e))?;
    }
    file.commit()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn csv_round_trips_header_and_values() {
        let t = parse_csv("t,mu1,energy\n0,1.5,2\n0.1,-2e-3,2\n", "x").unwrap();
        assert_eq!(t.rows(), 2);
        assert_eq!(t.column("mu1").unwrap(), &[1.5, -2e-3]);
        assert_eq!(t.momentum().len(), 1);
    }

    #[test]
    fn csv_errors_name_the_line() {
        let e = parse_csv("t,energy\n0,1\n0.1,x\n", "f.csv").unwrap_err();
        assert_eq!(e.to_string(), "f.csv:3: `energy`: `x` is not a number");
        let e = parse_csv("a,b\n", "f.csv").unwrap_err();
        assert!(e.to_string().contains("no `t` column"), "{e}");
    }

    #[test]
    fn relative_deviation_is_signed_and_relative_to_first() {
        assert_eq!(relative_deviation(&[-2.0, -2.0, -1.0]), vec![0.0, 0.0, 0.5]);
    }
}
