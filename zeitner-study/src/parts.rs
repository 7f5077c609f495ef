//! Results tables in Parquet: one file per finished batch (`parts/batch-NNNNNN.parquet`), and
//! the gathered `results.parquet`, with the same columns — `case`, the parameters, the outputs
//! (null where the case failed) and `error` (null where it succeeded).

use std::fs::File;
use std::path::Path;
use std::sync::Arc;

use parquet::basic::Repetition;
use parquet::data_type::{ByteArray, ByteArrayType, DoubleType, Int64Type};
use parquet::file::properties::WriterProperties;
use parquet::file::reader::{FileReader, SerializedFileReader};
use parquet::file::writer::SerializedFileWriter;
use parquet::record::Field;
use parquet::schema::parser::parse_message_type;

use crate::space::{Space, CASE_COLUMN, ERROR_COLUMN};

/// One case's row of a results table. In [`Study`](crate::Study)'s example.
#[derive(Clone, Debug, PartialEq)]
pub struct CaseResult {
    pub id: u64,
    /// In the order of the space's parameters.
    pub parameters: Vec<f64>,
    /// The outputs in the order the study names them, or the case's error as text.
    pub outcome: Result<Vec<f64>, String>,
}

fn schema(space: &Space) -> String {
    let mut message = format!("message results {{ REQUIRED INT64 {CASE_COLUMN};");
    for p in space.parameters() {
        message.push_str(&format!(" REQUIRED DOUBLE {};", p.name));
    }
    for o in space.outputs() {
        message.push_str(&format!(" OPTIONAL DOUBLE {o};"));
    }
    message.push_str(&format!(" OPTIONAL BYTE_ARRAY {ERROR_COLUMN} (UTF8); }}"));
    message
}

/// Writes `rows` as one Parquet file at `path`, by way of a temporary file renamed into place:
/// a run killed while writing leaves no part that looks finished.
pub fn write(path: &Path, space: &Space, rows: &[CaseResult]) -> Result<(), String> {
    let temporary = path.with_extension("parquet.partial");
    write_file(&temporary, space, rows).map_err(|e| format!("{}: {e}", temporary.display()))?;
    std::fs::rename(&temporary, path).map_err(|e| format!("{}: {e}", path.display()))
}

fn write_file(
    path: &Path,
    space: &Space,
    rows: &[CaseResult],
) -> Result<(), Box<dyn std::error::Error>> {
    let schema = Arc::new(parse_message_type(&schema(space))?);
    let properties = Arc::new(WriterProperties::builder().build());
    let mut writer = SerializedFileWriter::new(File::create(path)?, schema, properties)?;
    let mut group = writer.next_row_group()?;
    let (p, o) = (space.parameters().len(), space.outputs().len());
    let mut index = 0;
    while let Some(mut column) = group.next_column()? {
        if index == 0 {
            let ids: Vec<i64> = rows.iter().map(|r| r.id as i64).collect();
            column.typed::<Int64Type>().write_batch(&ids, None, None)?;
        } else if index <= p {
            let values: Vec<f64> = rows.iter().map(|r| r.parameters[index - 1]).collect();
            column
                .typed::<DoubleType>()
                .write_batch(&values, None, None)?;
        } else if index <= p + o {
            let k = index - 1 - p;
            let values: Vec<f64> = rows
                .iter()
                .filter_map(|r| r.outcome.as_ref().ok().map(|v| v[k]))
                .collect();
            let defined: Vec<i16> = rows.iter().map(|r| i16::from(r.outcome.is_ok())).collect();
            column
                .typed::<DoubleType>()
                .write_batch(&values, Some(&defined), None)?;
        } else {
            let errors: Vec<ByteArray> = rows
                .iter()
                .filter_map(|r| {
                    r.outcome
                        .as_ref()
                        .err()
                        .map(|e| ByteArray::from(e.as_str()))
                })
                .collect();
            let defined: Vec<i16> = rows.iter().map(|r| i16::from(r.outcome.is_err())).collect();
            column
                .typed::<ByteArrayType>()
                .write_batch(&errors, Some(&defined), None)?;
        }
        column.close()?;
        index += 1;
    }
    group.close()?;
    writer.close()?;
    Ok(())
}

/// Reads a results table written by [`write()`] for `space`, checking its columns.
pub fn read(path: &Path, space: &Space) -> Result<Vec<CaseResult>, String> {
    read_file(path, space).map_err(|e| format!("{}: {e}", path.display()))
}

fn read_file(path: &Path, space: &Space) -> Result<Vec<CaseResult>, Box<dyn std::error::Error>> {
    let reader = SerializedFileReader::new(File::open(path)?)?;
    let expected = parse_message_type(&schema(space))?;
    let found = reader.metadata().file_metadata().schema();
    let names = |t: &parquet::schema::types::Type| -> Vec<(String, Repetition)> {
        t.get_fields()
            .iter()
            .map(|f| (f.name().to_string(), f.get_basic_info().repetition()))
            .collect()
    };
    if names(found) != names(&expected) {
        return Err(format!("its columns are not this study's ({})", schema(space)).into());
    }
    let (p, o) = (space.parameters().len(), space.outputs().len());
    let mut rows = Vec::new();
    for row in reader.get_row_iter(None)? {
        let fields: Vec<Field> = row?.into_columns().into_iter().map(|(_, f)| f).collect();
        let double = |f: &Field| match f {
            Field::Double(x) => Ok(*x),
            other => Err(format!("expected a number, found {other:?}")),
        };
        let Field::Long(id) = fields[0] else {
            return Err("the case column holds no integer".into());
        };
        let parameters = fields[1..=p].iter().map(double).collect::<Result<_, _>>()?;
        let outcome = match &fields[p + o + 1] {
            Field::Str(error) => Err(error.clone()),
            _ => Ok(fields[p + 1..=p + o]
                .iter()
                .map(double)
                .collect::<Result<_, _>>()?),
        };
        rows.push(CaseResult {
            id: id as u64,
            parameters,
            outcome,
        });
    }
    Ok(rows)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::space::Parameter;

    #[test]
    fn a_part_reads_back_with_its_failures_as_values() {
        let space =
            Space::new(vec![Parameter::new("h3", 0.0, 10.0)], &["peak", "impacts"]).unwrap();
        let rows = vec![
            CaseResult {
                id: 4,
                parameters: vec![8.0],
                outcome: Ok(vec![1.5e6, 3.0]),
            },
            CaseResult {
                id: 9,
                parameters: vec![0.1],
                outcome: Err("StepSizeTooSmall at t = 0.3".into()),
            },
            CaseResult {
                id: 11,
                parameters: vec![f64::MIN_POSITIVE],
                outcome: Ok(vec![-0.0, f64::MAX]),
            },
        ];
        let path =
            std::env::temp_dir().join(format!("zeitner-study-part-{}.parquet", std::process::id()));
        write(&path, &space, &rows).unwrap();
        assert_eq!(read(&path, &space).unwrap(), rows);
        let other =
            Space::new(vec![Parameter::new("h2", 0.0, 10.0)], &["peak", "impacts"]).unwrap();
        assert!(read(&path, &other)
            .unwrap_err()
            .contains("not this study's"));
        std::fs::remove_file(&path).unwrap();
    }
}
