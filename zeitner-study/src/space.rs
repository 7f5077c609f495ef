//! What a study varies: named parameters, each with the range its cases must stay in.

use core::fmt;

/// One parameter of a study: the name of its column in a case table and its closed range.
///
/// ```
/// use zeitner_study::Parameter;
///
/// let stiffness = Parameter::new("k", 1e5, 1e7);
/// assert!(stiffness.contains(1e7) && !stiffness.contains(2e7));
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Parameter {
    pub name: String,
    pub low: f64,
    pub high: f64,
}

impl Parameter {
    pub fn new(name: impl Into<String>, low: f64, high: f64) -> Self {
        Parameter {
            name: name.into(),
            low,
            high,
        }
    }

    pub fn contains(&self, value: f64) -> bool {
        self.low <= value && value <= self.high
    }
}

/// The parameters of a study and the names of its outputs, checked once: names are distinct,
/// plain (letters, digits, `_`) and none is a column the results keep for themselves.
///
/// ```
/// use zeitner_study::{Parameter, Space, SpaceError};
///
/// let space = Space::new(vec![Parameter::new("k", 1e5, 1e7)], &["peak_force"])?;
/// assert_eq!((space.index("k"), space.outputs()), (Some(0), &["peak_force".to_string()][..]));
/// // The results keep a column `case` of their own.
/// let taken = Space::new(vec![Parameter::new("case", 0.0, 1.0)], &["y"]);
/// assert_eq!(taken, Err(SpaceError::BadName("case".into())));
/// # Ok::<(), SpaceError>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Space {
    parameters: Vec<Parameter>,
    outputs: Vec<String>,
}

/// Columns of every results table: the case's id and a failed case's error.
pub const CASE_COLUMN: &str = "case";
pub const ERROR_COLUMN: &str = "error";

/// A study's declaration that cannot run; [`Space`]'s example shows one.
#[derive(Clone, Debug, PartialEq)]
pub enum SpaceError {
    /// A name used twice among the parameters and outputs.
    Duplicate(String),
    /// A name that is not a plain identifier, or one of [`CASE_COLUMN`], [`ERROR_COLUMN`].
    BadName(String),
    /// A range that is empty or not finite.
    BadRange {
        parameter: String,
        low: f64,
        high: f64,
    },
    /// No parameters, or no outputs.
    Empty,
}

impl fmt::Display for SpaceError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SpaceError::Duplicate(name) => write!(f, "the name `{name}` is used twice"),
            SpaceError::BadName(name) => write!(
                f,
                "`{name}` cannot name a column: use letters, digits and `_`, and neither \
                 `{CASE_COLUMN}` nor `{ERROR_COLUMN}`"
            ),
            SpaceError::BadRange {
                parameter,
                low,
                high,
            } => write!(
                f,
                "parameter `{parameter}`: the range [{low}, {high}] must be finite with low ≤ high"
            ),
            SpaceError::Empty => write!(f, "a study needs at least one parameter and one output"),
        }
    }
}

impl std::error::Error for SpaceError {}

impl Space {
    pub fn new(parameters: Vec<Parameter>, outputs: &[&str]) -> Result<Self, SpaceError> {
        if parameters.is_empty() || outputs.is_empty() {
            return Err(SpaceError::Empty);
        }
        let names = parameters
            .iter()
            .map(|p| p.name.as_str())
            .chain(outputs.iter().copied());
        let mut seen: Vec<&str> = Vec::new();
        for name in names {
            if !is_plain(name) || name == CASE_COLUMN || name == ERROR_COLUMN {
                return Err(SpaceError::BadName(name.to_string()));
            }
            if seen.contains(&name) {
                return Err(SpaceError::Duplicate(name.to_string()));
            }
            seen.push(name);
        }
        for p in &parameters {
            if !(p.low.is_finite() && p.high.is_finite() && p.low <= p.high) {
                return Err(SpaceError::BadRange {
                    parameter: p.name.clone(),
                    low: p.low,
                    high: p.high,
                });
            }
        }
        Ok(Space {
            parameters,
            outputs: outputs.iter().map(|s| s.to_string()).collect(),
        })
    }

    pub fn parameters(&self) -> &[Parameter] {
        &self.parameters
    }

    pub fn outputs(&self) -> &[String] {
        &self.outputs
    }

    /// The index of parameter `name`.
    pub fn index(&self, name: &str) -> Option<usize> {
        self.parameters.iter().position(|p| p.name == name)
    }
}

fn is_plain(name: &str) -> bool {
    !name.is_empty()
        && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
        && !name.starts_with(|c: char| c.is_ascii_digit())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_must_be_distinct_plain_and_not_reserved() {
        let p = |n: &str| Parameter::new(n, 0.0, 1.0);
        assert!(Space::new(vec![p("h3"), p("clearance")], &["peak"]).is_ok());
        assert_eq!(
            Space::new(vec![p("h3"), p("h3")], &["peak"]),
            Err(SpaceError::Duplicate("h3".into()))
        );
        assert_eq!(
            Space::new(vec![p("h3")], &["h3"]),
            Err(SpaceError::Duplicate("h3".into()))
        );
        for bad in ["case", "error", "a b", "", "1x"] {
            assert_eq!(
                Space::new(vec![p(bad)], &["peak"]),
                Err(SpaceError::BadName(bad.into()))
            );
        }
        assert!(matches!(
            Space::new(vec![Parameter::new("x", 1.0, 0.0)], &["y"]),
            Err(SpaceError::BadRange { .. })
        ));
        assert_eq!(Space::new(vec![p("x")], &[]), Err(SpaceError::Empty));
    }
}
