//! Output helpers of the lab commands: JSON, and CSV flattened from the JSON (nested keys
//! joined with `_`, arrays indexed `_0`, `_1`, … or `_x`, `_y`, `_z` for three-vectors;
//! columns in alphabetical order of the flattened keys).

use carry_io::error::Failure;
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
