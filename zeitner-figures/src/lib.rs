//! The figures and tables of the examples and the benchmark: line charts and heat maps as SVG
//! and PNG, stacked in panels, with a font shipped in a crate so that a fresh machine needs no
//! system fonts; tables of numbers as CSV.

use std::path::Path;

use plotters::prelude::*;
use plotters::style::{register_font, FontStyle};

/// Writes a table of numbers as CSV: the header, then one record per row, each value in the
/// shortest form that reads back to the same `f64` (`1.5e-7`, `2.5e0`).
pub fn write_csv<Row: AsRef<[f64]>>(
    path: &Path,
    header: &[&str],
    rows: impl IntoIterator<Item = Row>,
) -> Result<(), Box<dyn std::error::Error>> {
    let mut writer = csv::Writer::from_path(path)?;
    writer.write_record(header)?;
    for row in rows {
        writer.write_record(row.as_ref().iter().map(|value| format!("{value:e}")))?;
    }
    writer.flush()?;
    Ok(())
}

/// One panel: a title, axis labels with units, and named series of `(x, y)` points.
pub struct Panel<'a> {
    pub title: &'a str,
    pub x_label: &'a str,
    pub y_label: &'a str,
    pub series: Vec<(&'a str, Vec<(f64, f64)>)>,
}

const COLORS: [RGBColor; 4] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(148, 103, 189),
];

fn register_fonts() {
    // Registering twice is harmless; the bytes are 'static.
    let _ = register_font(
        "sans-serif",
        FontStyle::Normal,
        epaint_default_fonts::UBUNTU_LIGHT,
    );
}

/// Writes the panels, one above the other, to `<stem>.svg` and `<stem>.png`.
pub fn write_panels(stem: &Path, panels: &[Panel<'_>]) -> Result<(), Box<dyn std::error::Error>> {
    register_fonts();
    let size = (1000, 330 * panels.len() as u32);
    let svg = stem.with_extension("svg");
    draw(SVGBackend::new(&svg, size).into_drawing_area(), panels)?;
    let png = stem.with_extension("png");
    draw(BitMapBackend::new(&png, size).into_drawing_area(), panels)?;
    Ok(())
}

fn draw<DB: DrawingBackend>(
    root: DrawingArea<DB, plotters::coord::Shift>,
    panels: &[Panel<'_>],
) -> Result<(), Box<dyn std::error::Error>>
where
    DB::ErrorType: 'static,
{
    root.fill(&WHITE)?;
    let areas = root.split_evenly((panels.len(), 1));
    for (panel, area) in panels.iter().zip(areas) {
        let points = panel.series.iter().flat_map(|(_, s)| s.iter());
        let (mut x0, mut x1, mut y0, mut y1) = (
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
        );
        for &(x, y) in points {
            x0 = x0.min(x);
            x1 = x1.max(x);
            y0 = y0.min(y);
            y1 = y1.max(y);
        }
        if y1 <= y0 || y1.is_nan() || y0.is_nan() {
            let pad = y0.abs().max(1e-300) * 0.1 + 1e-300;
            y0 -= pad;
            y1 += pad;
        }
        let margin = 0.05 * (y1 - y0);
        let mut chart = ChartBuilder::on(&area)
            .caption(panel.title, ("sans-serif", 20))
            .margin(12)
            .x_label_area_size(40)
            .y_label_area_size(90)
            .build_cartesian_2d(x0..x1, (y0 - margin)..(y1 + margin))?;
        chart
            .configure_mesh()
            .x_desc(panel.x_label)
            .y_desc(panel.y_label)
            .y_label_formatter(&|y| tick(*y, y1.abs().max(y0.abs())))
            .label_style(("sans-serif", 14))
            .draw()?;
        for (k, (name, series)) in panel.series.iter().enumerate() {
            let color = COLORS[k % COLORS.len()];
            chart
                .draw_series(LineSeries::new(
                    series.iter().copied(),
                    color.stroke_width(2),
                ))?
                .label(*name)
                .legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(2))
                });
        }
        if panel.series.len() > 1 {
            chart
                .configure_series_labels()
                .background_style(WHITE.mix(0.8))
                .border_style(BLACK)
                .label_font(("sans-serif", 14))
                .draw()?;
        }
    }
    root.present()?;
    Ok(())
}

/// Fixed notation where it reads well, scientific for very large or small ranges.
fn tick(value: f64, magnitude: f64) -> String {
    if (1e-2..1e5).contains(&magnitude) {
        let decimals = (2 - magnitude.log10().floor() as i32).clamp(0, 4) as usize;
        format!("{value:.decimals$}")
    } else {
        format!("{value:.2e}")
    }
}

/// Writes one log–log chart (e.g. error against CPU time) with a line and markers per series,
/// to `<stem>.svg` and `<stem>.png`. Non-positive values are left out (they have no logarithm).
pub fn write_log_log(stem: &Path, panel: &Panel<'_>) -> Result<(), Box<dyn std::error::Error>> {
    register_fonts();
    let svg = stem.with_extension("svg");
    draw_log_log(
        SVGBackend::new(&svg, (1000, 700)).into_drawing_area(),
        panel,
    )?;
    let png = stem.with_extension("png");
    draw_log_log(
        BitMapBackend::new(&png, (1000, 700)).into_drawing_area(),
        panel,
    )?;
    Ok(())
}

fn draw_log_log<DB: DrawingBackend>(
    root: DrawingArea<DB, plotters::coord::Shift>,
    panel: &Panel<'_>,
) -> Result<(), Box<dyn std::error::Error>>
where
    DB::ErrorType: 'static,
{
    root.fill(&WHITE)?;
    let positive = |s: &[(f64, f64)]| -> Vec<(f64, f64)> {
        s.iter()
            .copied()
            .filter(|&(x, y)| x > 0.0 && y > 0.0 && x.is_finite() && y.is_finite())
            .collect()
    };
    let series: Vec<(&str, Vec<(f64, f64)>)> = panel
        .series
        .iter()
        .map(|(n, s)| (*n, positive(s)))
        .collect();
    let (mut x0, mut x1, mut y0, mut y1) = (f64::INFINITY, 0.0f64, f64::INFINITY, 0.0f64);
    for &(x, y) in series.iter().flat_map(|(_, s)| s.iter()) {
        x0 = x0.min(x);
        x1 = x1.max(x);
        y0 = y0.min(y);
        y1 = y1.max(y);
    }
    if x1 <= 0.0 {
        (x0, x1, y0, y1) = (1e-6, 1.0, 1e-12, 1.0);
    }
    let mut chart = ChartBuilder::on(&root)
        .caption(panel.title, ("sans-serif", 22))
        .margin(16)
        .x_label_area_size(45)
        .y_label_area_size(80)
        .build_cartesian_2d(
            (x0 / 1.5..x1 * 1.5).log_scale(),
            (y0 / 3.0..y1 * 3.0).log_scale(),
        )?;
    chart
        .configure_mesh()
        .x_desc(panel.x_label)
        .y_desc(panel.y_label)
        .x_label_formatter(&|x| format!("{x:.0e}"))
        .y_label_formatter(&|y| format!("{y:.0e}"))
        .label_style(("sans-serif", 14))
        .draw()?;
    let palette = [
        RGBColor(31, 119, 180),
        RGBColor(214, 39, 40),
        RGBColor(44, 160, 44),
        RGBColor(148, 103, 189),
        RGBColor(255, 127, 14),
        RGBColor(140, 86, 75),
        RGBColor(227, 119, 194),
        RGBColor(23, 190, 207),
        RGBColor(188, 189, 34),
        RGBColor(127, 127, 127),
        RGBColor(0, 0, 0),
        RGBColor(120, 60, 160),
    ];
    for (k, (name, points)) in series.iter().enumerate() {
        let color = palette[k % palette.len()];
        chart
            .draw_series(LineSeries::new(
                points.iter().copied(),
                color.stroke_width(2),
            ))?
            .label(*name)
            .legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(2))
            });
        // Peers are drawn with hollow markers, our methods with filled ones.
        let filled = !name.starts_with("peer-");
        chart.draw_series(points.iter().map(|&p| {
            Circle::new(
                p,
                4,
                if filled {
                    color.filled()
                } else {
                    color.stroke_width(2)
                },
            )
        }))?;
    }
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperRight)
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .label_font(("sans-serif", 13))
        .draw()?;
    root.present()?;
    Ok(())
}

/// One map of a value over a plane: `(x, y, value)` points, on a grid (drawn as cells) or
/// scattered (drawn as dots), with a colour bar and an optional marked point.
pub struct Heatmap<'a> {
    pub title: &'a str,
    pub x_label: &'a str,
    pub y_label: &'a str,
    pub value_label: &'a str,
    pub points: Vec<(f64, f64, f64)>,
    pub marker: Option<(f64, f64)>,
    /// A path drawn over the map (an optimiser's iterates), white with its points marked.
    pub path: Vec<(f64, f64)>,
}

/// Writes the maps side by side to `<stem>.svg` and `<stem>.png`.
pub fn write_heatmaps(stem: &Path, maps: &[Heatmap<'_>]) -> Result<(), Box<dyn std::error::Error>> {
    register_fonts();
    let size = (620 * maps.len() as u32, 520);
    let svg = stem.with_extension("svg");
    draw_heatmaps(SVGBackend::new(&svg, size).into_drawing_area(), maps)?;
    let png = stem.with_extension("png");
    draw_heatmaps(BitMapBackend::new(&png, size).into_drawing_area(), maps)?;
    Ok(())
}

/// Viridis at five stops, interpolated linearly: ordered in lightness, readable in grey.
fn viridis(u: f64) -> RGBColor {
    const STOPS: [(f64, f64, f64); 5] = [
        (68.0, 1.0, 84.0),
        (59.0, 82.0, 139.0),
        (33.0, 145.0, 140.0),
        (94.0, 201.0, 98.0),
        (253.0, 231.0, 37.0),
    ];
    let u = if u.is_finite() {
        u.clamp(0.0, 1.0)
    } else {
        0.0
    };
    let s = u * 4.0;
    let i = (s.floor() as usize).min(3);
    let f = s - i as f64;
    let mix = |a: f64, b: f64| (a + (b - a) * f).round() as u8;
    let (a, b) = (STOPS[i], STOPS[i + 1]);
    RGBColor(mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}

fn distinct(values: impl Iterator<Item = f64>) -> Vec<f64> {
    let mut v: Vec<f64> = values.collect();
    v.sort_by(f64::total_cmp);
    v.dedup();
    v
}

fn draw_heatmaps<DB: DrawingBackend>(
    root: DrawingArea<DB, plotters::coord::Shift>,
    maps: &[Heatmap<'_>],
) -> Result<(), Box<dyn std::error::Error>>
where
    DB::ErrorType: 'static,
{
    root.fill(&WHITE)?;
    for (map, area) in maps.iter().zip(root.split_evenly((1, maps.len()))) {
        let (plot, bar) = area.split_horizontally(area.dim_in_pixel().0 as i32 - 110);
        let xs = distinct(map.points.iter().map(|p| p.0));
        let ys = distinct(map.points.iter().map(|p| p.1));
        let finite = map.points.iter().map(|p| p.2).filter(|v| v.is_finite());
        let (lo, hi) = finite.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
            (a.min(v), b.max(v))
        });
        let span = if hi > lo { hi - lo } else { 1.0 };
        let half = |axis: &[f64]| {
            if axis.len() > 1 {
                0.5 * (axis[axis.len() - 1] - axis[0]) / (axis.len() - 1) as f64
            } else {
                0.5
            }
        };
        let (dx, dy) = (half(&xs), half(&ys));
        let (x0, x1) = (xs[0] - dx, xs[xs.len() - 1] + dx);
        let (y0, y1) = (ys[0] - dy, ys[ys.len() - 1] + dy);
        let mut chart = ChartBuilder::on(&plot)
            .caption(map.title, ("sans-serif", 20))
            .margin(12)
            .x_label_area_size(45)
            .y_label_area_size(60)
            .build_cartesian_2d(x0..x1, y0..y1)?;
        chart
            .configure_mesh()
            .disable_mesh()
            .x_desc(map.x_label)
            .y_desc(map.y_label)
            .label_style(("sans-serif", 14))
            .draw()?;
        let on_grid = xs.len() * ys.len() == map.points.len();
        for &(x, y, v) in &map.points {
            let color = viridis((v - lo) / span);
            if on_grid {
                chart.draw_series(std::iter::once(Rectangle::new(
                    [(x - dx, y - dy), (x + dx, y + dy)],
                    color.filled(),
                )))?;
            } else {
                chart.draw_series(std::iter::once(Circle::new((x, y), 4, color.filled())))?;
            }
        }
        if !map.path.is_empty() {
            chart.draw_series(std::iter::once(PathElement::new(
                map.path.clone(),
                WHITE.stroke_width(2),
            )))?;
            chart.draw_series(
                map.path
                    .iter()
                    .map(|&p| Circle::new(p, 4, WHITE.stroke_width(2))),
            )?;
        }
        if let Some((x, y)) = map.marker {
            chart.draw_series(std::iter::once(Cross::new((x, y), 9, RED.stroke_width(3))))?;
        }
        let mut scale = ChartBuilder::on(&bar)
            .margin_top(44)
            .margin_bottom(57)
            .margin_right(8)
            .y_label_area_size(70)
            .caption(map.value_label, ("sans-serif", 14))
            .build_cartesian_2d(0.0..1.0, lo..lo + span)?;
        scale
            .configure_mesh()
            .disable_mesh()
            .disable_x_axis()
            .y_label_formatter(&|v| tick(*v, hi.abs().max(lo.abs())))
            .label_style(("sans-serif", 13))
            .draw()?;
        let steps = 100;
        scale.draw_series((0..steps).map(|i| {
            let (a, b) = (i as f64 / steps as f64, (i + 1) as f64 / steps as f64);
            Rectangle::new(
                [(0.0, lo + a * span), (1.0, lo + b * span)],
                viridis(a).filled(),
            )
        }))?;
    }
    root.present()?;
    Ok(())
}
