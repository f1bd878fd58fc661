//! Reading Python's JSON: numbers that may be bare `NaN`/`Infinity` tokens, and the schema's
//! errors named by the path of the offending field.

use serde_json::Value;

/// A golden file that does not match its schema.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Error {
    /// What was wrong, and where (`"cases[3].delivery.cor: not a number"`).
    pub message: String,
}

impl core::fmt::Display for Error {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(f, "golden file: {}", self.message)
    }
}

impl std::error::Error for Error {}

pub(crate) fn error(at: &str, what: &str) -> Error {
    Error {
        message: format!("{at}: {what}"),
    }
}

/// Every case of a golden file's `cases` array, read by `case`. Python's bare non-finite
/// tokens are turned into strings first.
pub(crate) fn parse_cases<C>(
    text: &str,
    case: impl Fn(&Fields<'_>) -> Result<C, Error>,
) -> Result<Vec<C>, Error> {
    let quoted = text
        .replace("-Infinity", "\"-inf\"")
        .replace("Infinity", "\"inf\"")
        .replace("NaN", "\"nan\"");
    let root: Value = serde_json::from_str(&quoted).map_err(|e| error("JSON", &e.to_string()))?;
    root.get("cases")
        .and_then(Value::as_array)
        .ok_or_else(|| error("cases", "missing"))?
        .iter()
        .enumerate()
        .map(|(i, c)| case(&Fields::new(c, format!("cases[{i}]"))))
        .collect()
}

/// One object of a case, by key.
pub(crate) struct Fields<'a> {
    pub(crate) value: &'a Value,
    pub(crate) at: String,
}

impl<'a> Fields<'a> {
    pub(crate) fn new(value: &'a Value, at: String) -> Self {
        Self { value, at }
    }

    fn path(&self, key: &str) -> String {
        format!("{}.{key}", self.at)
    }

    /// A nested object.
    pub(crate) fn object(&self, key: &str) -> Result<Fields<'a>, Error> {
        match self.value.get(key) {
            Some(v) if v.is_object() => Ok(Fields::new(v, self.path(key))),
            _ => Err(error(&self.path(key), "missing object")),
        }
    }

    /// A nested object that may be absent or null.
    pub(crate) fn optional_object(&self, key: &str) -> Result<Option<Fields<'a>>, Error> {
        match self.value.get(key) {
            None | Some(Value::Null) => Ok(None),
            Some(_) => self.object(key).map(Some),
        }
    }

    /// A number (or a non-finite token).
    pub(crate) fn num(&self, key: &str) -> Result<f64, Error> {
        let v = self
            .value
            .get(key)
            .ok_or_else(|| error(&self.path(key), "missing"))?;
        number(v).ok_or_else(|| error(&self.path(key), "not a number"))
    }

    /// A number that may be absent or null.
    pub(crate) fn optional_num(&self, key: &str) -> Result<Option<f64>, Error> {
        match self.value.get(key) {
            None | Some(Value::Null) => Ok(None),
            Some(_) => self.num(key).map(Some),
        }
    }

    /// A 3-vector.
    pub(crate) fn vec3(&self, key: &str) -> Result<[f64; 3], Error> {
        let v = self
            .value
            .get(key)
            .ok_or_else(|| error(&self.path(key), "missing"))?;
        vector(v).ok_or_else(|| error(&self.path(key), "not a 3-vector"))
    }

    /// A 3×3 matrix, row by row.
    pub(crate) fn matrix3(&self, key: &str) -> Result<[[f64; 3]; 3], Error> {
        let rows = self
            .value
            .get(key)
            .and_then(Value::as_array)
            .filter(|r| r.len() == 3)
            .ok_or_else(|| error(&self.path(key), "not a 3×3 matrix"))?;
        let row = |i: usize| vector(&rows[i]).ok_or_else(|| error(&self.path(key), "bad row"));
        Ok([row(0)?, row(1)?, row(2)?])
    }

    /// A string.
    pub(crate) fn string(&self, key: &str) -> Result<String, Error> {
        self.value
            .get(key)
            .and_then(Value::as_str)
            .map(str::to_owned)
            .ok_or_else(|| error(&self.path(key), "missing string"))
    }

    /// A string that may be absent.
    pub(crate) fn optional_string(&self, key: &str) -> Option<String> {
        self.value
            .get(key)
            .and_then(Value::as_str)
            .map(str::to_owned)
    }

    /// A boolean.
    pub(crate) fn boolean(&self, key: &str) -> Result<bool, Error> {
        self.value
            .get(key)
            .and_then(Value::as_bool)
            .ok_or_else(|| error(&self.path(key), "missing boolean"))
    }
}

fn number(v: &Value) -> Option<f64> {
    match v {
        Value::Number(n) => n.as_f64(),
        Value::String(s) => match s.as_str() {
            "nan" => Some(f64::NAN),
            "inf" => Some(f64::INFINITY),
            "-inf" => Some(f64::NEG_INFINITY),
            _ => None,
        },
        _ => None,
    }
}

fn vector(v: &Value) -> Option<[f64; 3]> {
    match v.as_array()?.as_slice() {
        [x, y, z] => Some([number(x)?, number(y)?, number(z)?]),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::parse_cases;

    #[test]
    fn a_malformed_case_names_its_field() {
        let text = r#"{"cases": [{"x": 1.5}, {"x": NaN}, {"x": "one"}]}"#;
        let err = parse_cases(text, |c| c.num("x")).expect_err("a bad number");
        assert_eq!(err.message, "cases[2].x: not a number");
        let ok = parse_cases(r#"{"cases": [{"x": -Infinity}]}"#, |c| c.num("x"));
        assert_eq!(ok, Ok(vec![f64::NEG_INFINITY]));
        assert!(parse_cases(r#"{"other": []}"#, |c| c.num("x")).is_err());
    }
}
