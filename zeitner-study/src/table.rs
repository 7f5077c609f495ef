//! A table of cases: one row of parameter values per case, with the case's id. Made from a grid,
//! a Sobol sample or a CSV file, and checked against the study's [`Space`] before anything runs.

use core::fmt;
use std::path::Path;

use crate::space::{Space, CASE_COLUMN};

/// Cases in rows: `values[row * width + column]` in the order of the space's parameters.
///
/// ```
/// use zeitner_study::{CaseTable, Parameter, Space, TableError};
///
/// let space = Space::new(
///     vec![Parameter::new("k", 1.0, 3.0), Parameter::new("gap", 0.0, 0.01)],
///     &["peak_force"],
/// )?;
/// let grid = CaseTable::grid(&space, &[3, 2])?;
/// assert_eq!((grid.len(), grid.row(1), grid.row(5)), (6, &[1.0, 0.01][..], &[3.0, 0.01][..]));
/// let sample = CaseTable::sobol(&space, 16, 7)?;
/// assert!((0..sample.len()).all(|r| space.parameters()[0].contains(sample.row(r)[0])));
/// // A case outside its parameter's range is refused, naming the row and the column.
/// let outside = CaseTable::from_rows(&space, vec![0], &[vec![4.0, 0.0]]);
/// assert!(matches!(outside, Err(TableError::OutOfRange { row: 1, ref column, .. }) if column == "k"));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct CaseTable {
    names: Vec<String>,
    ids: Vec<u64>,
    values: Vec<f64>,
}

/// A case table that cannot run, with the place to mend ([`CaseTable`]'s example shows one). Rows count from 1, the first row of
/// values (line 2 of a CSV file).
#[derive(Clone, Debug, PartialEq)]
pub enum TableError {
    MissingColumn {
        column: String,
    },
    /// A column the study has no parameter for (a misspelt name would otherwise be ignored).
    UnknownColumn {
        column: String,
    },
    /// A row with more or fewer cells than the header.
    Ragged {
        row: usize,
        expected: usize,
        found: usize,
    },
    NotANumber {
        row: usize,
        column: String,
        text: String,
    },
    NotFinite {
        row: usize,
        column: String,
        value: f64,
    },
    OutOfRange {
        row: usize,
        column: String,
        value: f64,
        low: f64,
        high: f64,
    },
    DuplicateId {
        row: usize,
        id: u64,
        first_row: usize,
    },
    Empty,
    /// More parameters than the Sobol sequence has dimensions.
    TooManyDimensions {
        parameters: usize,
        limit: usize,
    },
    /// A grid given a number of points per axis for another number of parameters, or 0 points.
    BadGrid {
        parameters: usize,
        axes: usize,
    },
    Unreadable {
        path: String,
        message: String,
    },
}

impl fmt::Display for TableError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            TableError::MissingColumn { column } => {
                write!(f, "the case table has no column `{column}`")
            }
            TableError::UnknownColumn { column } => write!(
                f,
                "the case table's column `{column}` is no parameter of the study"
            ),
            TableError::Ragged { row, expected, found } => {
                write!(f, "row {row}: {found} cells, the header has {expected}")
            }
            TableError::NotANumber { row, column, text } => {
                write!(f, "row {row}, column `{column}`: `{text}` is not a number")
            }
            TableError::NotFinite { row, column, value } => {
                write!(f, "row {row}, column `{column}`: {value} is not finite")
            }
            TableError::OutOfRange {
                row,
                column,
                value,
                low,
                high,
            } => write!(
                f,
                "row {row}, column `{column}`: {value} is outside the declared range [{low}, {high}]"
            ),
            TableError::DuplicateId { row, id, first_row } => {
                write!(f, "row {row}: case id {id} is already that of row {first_row}")
            }
            TableError::Empty => write!(f, "the case table has no cases"),
            TableError::TooManyDimensions { parameters, limit } => write!(
                f,
                "a Sobol sample has at most {limit} dimensions; the study has {parameters} parameters"
            ),
            TableError::BadGrid { parameters, axes } => write!(
                f,
                "a grid needs a number of points ≥ 1 for each of the {parameters} parameters \
                 (or one for all); got {axes}"
            ),
            TableError::Unreadable { path, message } => write!(f, "{path}: {message}"),
        }
    }
}

impl std::error::Error for TableError {}

impl CaseTable {
    /// Rows of values (in the space's parameter order) with their ids, checked.
    pub fn from_rows(space: &Space, ids: Vec<u64>, rows: &[Vec<f64>]) -> Result<Self, TableError> {
        let width = space.parameters().len();
        let mut values = Vec::with_capacity(rows.len() * width);
        for (r, row) in rows.iter().enumerate() {
            if row.len() != width {
                return Err(TableError::Ragged {
                    row: r + 1,
                    expected: width,
                    found: row.len(),
                });
            }
            values.extend_from_slice(row);
        }
        let table = CaseTable {
            names: space.parameters().iter().map(|p| p.name.clone()).collect(),
            ids,
            values,
        };
        table.check(space)?;
        Ok(table)
    }

    /// Every combination of `points` values per parameter, evenly spaced over its range (one
    /// point: the range's middle); `points` holds one count for every parameter, or one for all.
    /// Ids count from 0 with the last parameter varying fastest.
    pub fn grid(space: &Space, points: &[usize]) -> Result<Self, TableError> {
        let parameters = space.parameters();
        let counts: Vec<usize> = match points.len() {
            1 => vec![points[0]; parameters.len()],
            n if n == parameters.len() => points.to_vec(),
            _ => Vec::new(),
        };
        if counts.is_empty() || counts.contains(&0) {
            return Err(TableError::BadGrid {
                parameters: parameters.len(),
                axes: points.len(),
            });
        }
        let axes: Vec<Vec<f64>> = parameters
            .iter()
            .zip(&counts)
            .map(|(p, &n)| match n {
                1 => vec![0.5 * (p.low + p.high)],
                _ => (0..n)
                    .map(|i| p.low + (p.high - p.low) * i as f64 / (n - 1) as f64)
                    .collect(),
            })
            .collect();
        let total: usize = counts.iter().product();
        let rows: Vec<Vec<f64>> = (0..total)
            .map(|mut index| {
                let mut row = vec![0.0; counts.len()];
                for axis in (0..counts.len()).rev() {
                    row[axis] = axes[axis][index % counts[axis]];
                    index /= counts[axis];
                }
                row
            })
            .collect();
        Self::from_rows(space, (0..total as u64).collect(), &rows)
    }

    /// `n` points of an Owen-scrambled Sobol sequence (Burley 2020) scaled to the ranges; the
    /// same `seed` gives the same table.
    pub fn sobol(space: &Space, n: usize, seed: u32) -> Result<Self, TableError> {
        let parameters = space.parameters();
        if parameters.len() > sobol_burley::NUM_DIMENSIONS as usize {
            return Err(TableError::TooManyDimensions {
                parameters: parameters.len(),
                limit: sobol_burley::NUM_DIMENSIONS as usize,
            });
        }
        let rows: Vec<Vec<f64>> = (0..n as u32)
            .map(|i| {
                parameters
                    .iter()
                    .enumerate()
                    .map(|(d, p)| {
                        let u = f64::from(sobol_burley::sample(i, d as u32, seed));
                        p.low + (p.high - p.low) * u
                    })
                    .collect()
            })
            .collect();
        Self::from_rows(space, (0..n as u64).collect(), &rows)
    }

    /// A CSV file with a header naming every parameter (in any order) and, optionally, a `case`
    /// column of distinct non-negative integer ids (else the ids are the rows' indices from 0).
    pub fn read_csv(space: &Space, path: &Path) -> Result<Self, TableError> {
        let unreadable = |message: String| TableError::Unreadable {
            path: path.display().to_string(),
            message,
        };
        let mut reader = csv::ReaderBuilder::new()
            .flexible(true)
            .from_path(path)
            .map_err(|e| unreadable(e.to_string()))?;
        let header: Vec<String> = reader
            .headers()
            .map_err(|e| unreadable(e.to_string()))?
            .iter()
            .map(|s| s.trim().to_string())
            .collect();
        let id_column = header.iter().position(|h| h == CASE_COLUMN);
        for h in &header {
            if h != CASE_COLUMN && space.index(h).is_none() {
                return Err(TableError::UnknownColumn { column: h.clone() });
            }
        }
        let columns: Vec<usize> = space
            .parameters()
            .iter()
            .map(|p| {
                header
                    .iter()
                    .position(|h| *h == p.name)
                    .ok_or_else(|| TableError::MissingColumn {
                        column: p.name.clone(),
                    })
            })
            .collect::<Result<_, _>>()?;
        let (mut ids, mut rows) = (Vec::new(), Vec::new());
        for (r, record) in reader.records().enumerate() {
            let record = record.map_err(|e| unreadable(e.to_string()))?;
            let row = r + 1;
            if record.len() != header.len() {
                return Err(TableError::Ragged {
                    row,
                    expected: header.len(),
                    found: record.len(),
                });
            }
            let cell = |c: usize| record[c].trim();
            ids.push(match id_column {
                Some(c) => cell(c).parse::<u64>().map_err(|_| TableError::NotANumber {
                    row,
                    column: CASE_COLUMN.into(),
                    text: cell(c).into(),
                })?,
                None => r as u64,
            });
            let values = columns
                .iter()
                .map(|&c| {
                    cell(c).parse::<f64>().map_err(|_| TableError::NotANumber {
                        row,
                        column: header[c].clone(),
                        text: cell(c).into(),
                    })
                })
                .collect::<Result<Vec<f64>, _>>()?;
            rows.push(values);
        }
        Self::from_rows(space, ids, &rows)
    }

    /// Writes the table as CSV (`case` first, then the parameters), every value to the bit.
    pub fn write_csv(&self, path: &Path) -> std::io::Result<()> {
        let mut text = String::from(CASE_COLUMN);
        for name in &self.names {
            text.push(',');
            text.push_str(name);
        }
        text.push('\n');
        for row in 0..self.len() {
            text.push_str(&self.ids[row].to_string());
            for value in self.row(row) {
                // `{:?}` prints the shortest text that reads back to the same f64.
                text.push_str(&format!(",{value:?}"));
            }
            text.push('\n');
        }
        std::fs::write(path, text)
    }

    pub fn len(&self) -> usize {
        self.ids.len()
    }

    pub fn is_empty(&self) -> bool {
        self.ids.is_empty()
    }

    pub fn id(&self, row: usize) -> u64 {
        self.ids[row]
    }

    /// Row `row`'s values in the space's parameter order.
    pub fn row(&self, row: usize) -> &[f64] {
        let width = self.names.len();
        &self.values[row * width..(row + 1) * width]
    }

    pub fn names(&self) -> &[String] {
        &self.names
    }

    fn check(&self, space: &Space) -> Result<(), TableError> {
        if self.is_empty() {
            return Err(TableError::Empty);
        }
        let mut first_row = std::collections::HashMap::with_capacity(self.len());
        for r in 0..self.len() {
            for (p, &value) in space.parameters().iter().zip(self.row(r)) {
                let column = p.name.clone();
                if !value.is_finite() {
                    return Err(TableError::NotFinite {
                        row: r + 1,
                        column,
                        value,
                    });
                }
                if !p.contains(value) {
                    let (low, high) = (p.low, p.high);
                    return Err(TableError::OutOfRange {
                        row: r + 1,
                        column,
                        value,
                        low,
                        high,
                    });
                }
            }
            if let Some(&first) = first_row.get(&self.ids[r]) {
                return Err(TableError::DuplicateId {
                    row: r + 1,
                    id: self.ids[r],
                    first_row: first,
                });
            }
            first_row.insert(self.ids[r], r + 1);
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::space::Parameter;

    fn space() -> Space {
        let parameters = vec![
            Parameter::new("h3", 4.0, 12.0),
            Parameter::new("clearance", 0.0, 0.01),
        ];
        Space::new(parameters, &["peak"]).unwrap()
    }

    fn read(text: &str) -> Result<CaseTable, TableError> {
        let dir = std::env::temp_dir().join(format!("zeitner-study-table-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join(format!(
            "{:x}.csv",
            text.len() * 7919 + text.bytes().map(usize::from).sum::<usize>()
        ));
        std::fs::write(&path, text).unwrap();
        let table = CaseTable::read_csv(&space(), &path);
        std::fs::remove_file(&path).unwrap();
        table
    }

    #[test]
    fn a_grid_spans_the_ranges_with_the_last_parameter_fastest() {
        let table = CaseTable::grid(&space(), &[3, 2]).unwrap();
        assert_eq!(table.len(), 6);
        assert_eq!(table.row(0), &[4.0, 0.0]);
        assert_eq!(table.row(1), &[4.0, 0.01]);
        assert_eq!(table.row(5), &[12.0, 0.01]);
        assert_eq!(
            CaseTable::grid(&space(), &[1]).unwrap().row(0),
            &[8.0, 0.005]
        );
        assert!(matches!(
            CaseTable::grid(&space(), &[2, 2, 2]),
            Err(TableError::BadGrid { .. })
        ));
    }

    #[test]
    fn a_sobol_sample_is_in_range_repeatable_and_fills_the_square_evenly() {
        let a = CaseTable::sobol(&space(), 256, 7).unwrap();
        assert_eq!(a, CaseTable::sobol(&space(), 256, 7).unwrap());
        assert_ne!(a, CaseTable::sobol(&space(), 256, 8).unwrap());
        // A (t, m, s)-net: every one of 16 × 16 cells of the square holds exactly one point.
        let mut cells = std::collections::HashSet::new();
        for r in 0..a.len() {
            let [h3, c] = [a.row(r)[0], a.row(r)[1]];
            cells.insert((((h3 - 4.0) / 8.0 * 16.0) as u32, (c / 0.01 * 16.0) as u32));
        }
        assert_eq!(cells.len(), 256);
    }

    #[test]
    fn a_csv_table_reads_in_any_column_order_and_writes_back_to_the_bit() {
        let table = read("clearance,case,h3\n0.001,7,4.5\n0.002,3,11.25\n").unwrap();
        assert_eq!((table.id(0), table.row(0)), (7, &[4.5, 0.001][..]));
        assert_eq!((table.id(1), table.row(1)), (3, &[11.25, 0.002][..]));
        let sobol = CaseTable::sobol(&space(), 10, 1).unwrap();
        let path =
            std::env::temp_dir().join(format!("zeitner-study-back-{}.csv", std::process::id()));
        sobol.write_csv(&path).unwrap();
        let back = CaseTable::read_csv(&space(), &path).unwrap();
        std::fs::remove_file(&path).unwrap();
        assert_eq!(back, sobol);
    }

    #[test]
    fn a_bad_table_is_refused_naming_its_row_and_column() {
        let cases = [
            (
                "h3\n5\n",
                TableError::MissingColumn {
                    column: "clearance".into(),
                },
            ),
            (
                "h3,clearence\n5,0.001\n",
                TableError::UnknownColumn {
                    column: "clearence".into(),
                },
            ),
            (
                "h3,clearance\n5,0.001\n6,NaN\n",
                TableError::NotFinite {
                    row: 2,
                    column: "clearance".into(),
                    value: f64::NAN,
                },
            ),
            (
                "h3,clearance\n5,0.001\n6,x\n",
                TableError::NotANumber {
                    row: 2,
                    column: "clearance".into(),
                    text: "x".into(),
                },
            ),
            (
                "h3,clearance\n5,0.001\n13,0.001\n",
                TableError::OutOfRange {
                    row: 2,
                    column: "h3".into(),
                    value: 13.0,
                    low: 4.0,
                    high: 12.0,
                },
            ),
            (
                "case,h3,clearance\n1,5,0.001\n2,5,0.002\n1,6,0.003\n",
                TableError::DuplicateId {
                    row: 3,
                    id: 1,
                    first_row: 1,
                },
            ),
            (
                "h3,clearance\n5,0.001\n6\n",
                TableError::Ragged {
                    row: 2,
                    expected: 2,
                    found: 1,
                },
            ),
            ("h3,clearance\n", TableError::Empty),
        ];
        for (text, expected) in cases {
            let got = read(text).unwrap_err();
            // NaN ≠ NaN: compare what the user reads.
            assert_eq!(got.to_string(), expected.to_string(), "{text}");
        }
    }
}
