//! The header of a small CSV table (the measured data of `../shared/data`): column names,
//! trimmed, looked up by name.

/// A CSV header line's column names.
#[derive(Debug, Clone)]
pub struct Header<'a>(Vec<&'a str>);

impl<'a> Header<'a> {
    /// The names of `line`, split at commas and trimmed.
    #[must_use]
    pub fn of(line: &'a str) -> Self {
        Self(line.split(',').map(str::trim).collect())
    }

    /// The index of column `name`.
    ///
    /// # Errors
    /// `no column 'name'`.
    pub fn column(&self, name: &str) -> Result<usize, String> {
        self.0
            .iter()
            .position(|h| *h == name)
            .ok_or(format!("no column '{name}'"))
    }

    /// The indices of columns `names`, in order.
    ///
    /// # Errors
    /// `no column 'name'` for the first one missing.
    pub fn columns<const N: usize>(&self, names: [&str; N]) -> Result<[usize; N], String> {
        let mut out = [0; N];
        for (i, name) in out.iter_mut().zip(names) {
            *i = self.column(name)?;
        }
        Ok(out)
    }

    /// The name of column `i` (empty past the end).
    #[must_use]
    pub fn name(&self, i: usize) -> &'a str {
        self.0.get(i).copied().unwrap_or("")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finds_trimmed_names_and_names_a_missing_one() {
        let h = Header::of("a, b ,c");
        assert_eq!(h.column("b"), Ok(1));
        assert_eq!(h.name(2), "c");
        assert_eq!(h.name(3), "");
        assert_eq!(h.column("d"), Err("no column 'd'".to_owned()));
        assert_eq!(h.columns(["c", "a"]), Ok([2, 0]));
        assert_eq!(h.columns(["a", "e"]), Err("no column 'e'".to_owned()));
    }
}
