//! Output helpers of the lab commands: JSON, and CSV flattened from the JSON (nested keys
//! joined with `_`, arrays indexed `_0`, `_1`, … or `_x`, `_y`, `_z` for three-vectors;
//! columns in alphabetical order of the flattened keys).

use carry_io::error::{Failure, InputError};
use serde::Serialize;
use serde_json::Value;
use std::fmt::Write as _;

/// Pretty JSON with a final newline.
///
/// # Errors
/// Serialisation failure (a bug).
pub fn json<T: Serialize>(value: &T) -> Result<String, Failure> {
    let mut s = serde_json::to_string_pretty(value).map_err(|e| Failure::Other(e.to_string()))?;
    s.push('\n');
    Ok(s)
}

fn flatten(prefix: &str, v: &Value, out: &mut Vec<(String, String)>) {
    let key = |k: &str| {
        if prefix.is_empty() {
            k.to_owned()
        } else {
            format!("{prefix}_{k}")
        }
    };
    match v {
        Value::Object(map) => {
            for (k, v) in map {
                flatten(&key(k), v, out);
            }
        }
        Value::Array(a) => {
            let names = ["x", "y", "z"];
            for (i, v) in a.iter().enumerate() {
                let suffix = if a.len() == 3 {
                    names
                        .get(i)
                        .map_or_else(|| i.to_string(), |s| (*s).to_owned())
                } else {
                    i.to_string()
                };
                flatten(&key(&suffix), v, out);
            }
        }
        Value::Null => out.push((prefix.to_owned(), String::new())),
        Value::String(s) => {
            let quoted = if s.contains([',', '"', '\n']) {
                format!("\"{}\"", s.replace('"', "\"\""))
            } else {
                s.clone()
            };
            out.push((prefix.to_owned(), quoted));
        }
        other => out.push((prefix.to_owned(), other.to_string())),
    }
}

/// CSV of `rows` (each serialised and flattened); the header is every key in first-seen
/// order, and a row without a key (e.g. a failed shot's results) leaves it empty.
///
/// # Errors
/// Serialisation failure (a bug).
pub fn csv<T: Serialize>(rows: &[T]) -> Result<String, Failure> {
    let mut flat = Vec::with_capacity(rows.len());
    let mut header: Vec<String> = Vec::new();
    for row in rows {
        let v = serde_json::to_value(row).map_err(|e| Failure::Other(e.to_string()))?;
        let mut fields = Vec::new();
        flatten("", &v, &mut fields);
        for (k, _) in &fields {
            if !header.contains(k) {
                header.push(k.clone());
            }
        }
        flat.push(fields);
    }
    let mut s = header.join(",");
    s.push('\n');
    for fields in &flat {
        let values: Vec<&str> = header
            .iter()
            .map(|k| {
                fields
                    .iter()
                    .find(|(key, _)| key == k)
                    .map_or("", |(_, v)| v.as_str())
            })
            .collect();
        let _ = writeln!(s, "{}", values.join(","));
    }
    Ok(s)
}

/// A CSV field: quoted (with `"` doubled) when it holds a comma, a quote or a line break.
pub(crate) fn csv_text(text: &str) -> String {
    if text.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", text.replace('"', "\"\""))
    } else {
        text.to_owned()
    }
}

/// The label of a record: column `label` of the columns the input's header kept
/// (`kept[label]` is its index in the record), as text.
pub(crate) fn label_column(
    label: Option<usize>,
    kept: &[usize],
) -> impl Fn(&csv::ByteRecord) -> Option<String> + '_ {
    move |rec| {
        label
            .and_then(|i| kept.get(i))
            .and_then(|&i| rec.get(i))
            .map(|l| String::from_utf8_lossy(l).into_owned())
    }
}

/// The table of a batch analysis (`carry batch estimate`, from ball data or from the
/// flight): one row per input record, `line` (the record's line in the input), `label`
/// when the input has one (`has_label`, each row's from `label`), the record's `columns` and `error`; as CSV with a header, or
/// as JSON lines (the record's fields, or `error`). A failed row keeps its line with empty
/// values and the error `line N: message`.
pub(crate) fn batch_table<T: Serialize>(
    records: &[csv::ByteRecord],
    results: &[Result<T, InputError>],
    has_label: bool,
    label: impl Fn(&csv::ByteRecord) -> Option<String>,
    columns: &[&str],
    cells: impl Fn(&T) -> Vec<String>,
    json: bool,
) -> String {
    let mut out = String::new();
    if !json {
        out.push_str("line");
        if has_label {
            out.push_str(",label");
        }
        for c in columns.iter().chain(&["error"]) {
            out.push(',');
            out.push_str(c);
        }
        out.push('\n');
    }
    for (rec, result) in records.iter().zip(results) {
        let line = rec.position().map_or(0, csv::Position::line);
        let label_text = label(rec);
        let error = result
            .as_ref()
            .err()
            .map(|e| format!("line {line}: {}", e.as_column()));
        if json {
            let mut obj = serde_json::Map::new();
            obj.insert("line".into(), line.into());
            if let Some(l) = &label_text {
                obj.insert("label".into(), l.clone().into());
            }
            if let Ok(Ok(Value::Object(fields))) = result.as_ref().map(serde_json::to_value) {
                obj.extend(fields);
            }
            if let Some(e) = error {
                obj.insert("error".into(), e.into());
            }
            out.push_str(&Value::Object(obj).to_string());
            out.push('\n');
        } else {
            let _ = write!(out, "{line}");
            if has_label {
                let _ = write!(out, ",{}", csv_text(label_text.as_deref().unwrap_or("")));
            }
            match result {
                Ok(r) => {
                    for c in cells(r) {
                        let _ = write!(out, ",{}", csv_text(&c));
                    }
                    out.push_str(",\n");
                }
                Err(_) => {
                    out.push_str(&",".repeat(columns.len()));
                    let _ = writeln!(out, ",{}", csv_text(error.as_deref().unwrap_or("")));
                }
            }
        }
    }
    out
}
