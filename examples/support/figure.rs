//! Line charts as SVG and PNG, stacked in panels, with a font shipped in a crate so that a
//! fresh machine needs no system fonts.
#![allow(dead_code)] // shared by the example and the benchmark; each uses a part

use std::path::Path;

use plotters::prelude::*;
use plotters::style::{register_font, FontStyle};

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
