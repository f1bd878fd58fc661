//! `carry batch`: many shots from a CSV file, in parallel, output in input order.
//!
//! Throughput design: the `csv` crate splits records into reused [`ByteRecord`]s, a chunk
//! at a time; rayon parses, computes and formats sub-chunks in parallel, each into one
//! byte buffer (floats by `ryu`, no per-field allocation); the buffers are written in order
//! through a `BufWriter`. A bad row becomes an error row (naming the line and the column)
//! and the rest continue.

use crate::compute::{self, Mode, Numerics};
use crate::error::{Failure, InputError};
use crate::params::{Key, Params};
use crate::report::{self, Floats};
use crate::scene::SCENE_KEYS;
use crate::units::Units;
use csv::ByteRecord;
use rayon::prelude::*;
use std::io::{IsTerminal as _, Read, Write};
use std::path::PathBuf;

/// Records read per chunk.
const CHUNK: usize = 16 * 1024;
/// Records per parallel work item.
const PIECE: usize = 256;
/// Input size above which a progress bar is shown (bytes), when stderr is a terminal.
const PROGRESS_BYTES: u64 = 2 * 1024 * 1024;

/// A batch run.
#[derive(Debug, Clone)]
pub struct Job {
    /// What to compute.
    pub mode: Mode,
    /// Values for columns the file does not have (command-line options and defaults).
    pub base: Params,
    /// Numerics.
    pub numerics: Numerics,
    /// Units of the input values.
    pub units: Units,
    /// JSON lines instead of CSV.
    pub json: bool,
    /// Input file, `-` for stdin.
    pub input: PathBuf,
    /// Worker threads.
    pub threads: Option<usize>,
    /// Show a progress bar if large and on a terminal.
    pub progress: bool,
}

/// Whether `key` is an input of `mode`.
#[must_use]
pub fn applies(mode: Mode, key: Key) -> bool {
    use Key::*;
    match key {
        BallMass | BallRadius => true,
        ClubSpeed | AttackAngle | ClubPath | FaceAngle | DynamicLoft | Lie | ClubSpin
        | ClubSpinX | ClubSpinY | ClubSpinZ | ImpactHeight | ImpactToe | Cor | SpinAxisShare
        | Convention | Club | Contact | ClubMass | ClubInertia | Loft | Bulge | Roll
        | FaceDepthRadius | CgToFace | CgToFaceX | CgToFaceY | CgToFaceZ => mode != Mode::Flight,
        BallSpeed | LaunchAngle | LaunchDirection | Backspin | Sidespin | Spin | SpinAxis => {
            mode == Mode::Flight
        }
        k => SCENE_KEYS.contains(&k) && mode != Mode::Impact,
    }
}

/// Whether the output has the ground's columns: the command line or the scene file names a
/// ground, or the input has a ground column.
fn ground_columns(job: &Job, cols: &Columns) -> bool {
    !job.base.scene.ground.is_empty() || cols.keys().any(Key::is_ground)
}

/// The output columns of one `carry batch` that the others read as inputs (the launch, in
/// SI whatever `--units`): `carry batch impact --input d.csv | carry batch flight --input -`.
/// `spin_rpm` and `spin_axis_deg` are read only without `backspin_rpm` and `sidespin_rpm`
/// (the output has all four; the pairs exclude each other as inputs).
pub const OUTPUT_INPUTS: &[(&str, Key)] = &[
    ("ball_speed_mps", Key::BallSpeed),
    ("launch_angle_deg", Key::LaunchAngle),
    ("launch_direction_deg", Key::LaunchDirection),
    ("backspin_rpm", Key::Backspin),
    ("sidespin_rpm", Key::Sidespin),
    ("spin_rpm", Key::Spin),
    ("spin_axis_deg", Key::SpinAxis),
];

/// Whether `name` is a column some `carry batch` writes: `line`, `error`, or a result
/// column of any mode.
#[must_use]
pub fn is_output_column(name: &str) -> bool {
    name == "line"
        || name == "error"
        || [Mode::Impact, Mode::Shot]
            .iter()
            .any(|&m| report::csv_columns(m, true).contains(&name))
}

/// One input column: its index, its key, and whether its values are SI (an output
/// column read back) rather than in `--units`.
#[derive(Debug, Clone, Copy)]
struct Input {
    index: usize,
    key: Key,
    si: bool,
}

/// The meaning of each input column.
#[derive(Debug, Clone)]
pub struct Columns {
    keys: Vec<Input>,
    /// Index of the `label` column, if any.
    pub label: Option<usize>,
    /// Index of an `error` column (a batch's output read back): a row with an error is an
    /// error row again.
    error: Option<usize>,
    width: usize,
}

impl Columns {
    /// Maps a header to keys: option names in snake_case, and the output columns of the
    /// other `carry batch` commands (those that are inputs of `mode` are read, in SI; the
    /// rest are ignored).
    ///
    /// # Errors
    /// On `--input` for an unknown, duplicate or inapplicable column.
    pub fn from_header(header: &ByteRecord, mode: Mode) -> Result<Self, InputError> {
        let names: Vec<String> = header
            .iter()
            .map(|raw| {
                let name = String::from_utf8_lossy(raw);
                name.trim().trim_start_matches('\u{feff}').to_owned()
            })
            .collect();
        let has = |n: &str| names.iter().any(|m| m == n);
        let spin_pair = has("backspin_rpm") || has("sidespin_rpm");
        let mut keys: Vec<Input> = Vec::new();
        let mut label = None;
        let mut error = None;
        for (i, name) in names.iter().enumerate() {
            let name = name.as_str();
            if name == "label" {
                label = Some(i);
                continue;
            }
            if name == "error" {
                error = Some(i);
                continue;
            }
            let (key, si) = if let Some(key) = Key::find(name) {
                if !applies(mode, key) {
                    return Err(InputError::new(
                        "input",
                        format!("line 1: column '{name}' is not an input of this command"),
                    ));
                }
                (key, false)
            } else if is_output_column(name) {
                let alias = OUTPUT_INPUTS
                    .iter()
                    .find(|(n, _)| *n == name)
                    .map(|(_, k)| *k);
                match alias {
                    Some(Key::Spin | Key::SpinAxis) if spin_pair => continue,
                    Some(key) if applies(mode, key) => (key, true),
                    // Another command's result: not an input here.
                    _ => continue,
                }
            } else {
                return Err(InputError::new(
                    "input",
                    format!(
                        "line 1: unknown column '{name}' (columns are option names in snake_case, e.g. club_speed, or another batch's output columns)"
                    ),
                ));
            };
            if keys.iter().any(|c| c.key == key) {
                return Err(InputError::new(
                    "input",
                    format!("line 1: column '{name}' appears twice"),
                ));
            }
            keys.push(Input { index: i, key, si });
        }
        Ok(Self {
            keys,
            label,
            error,
            width: header.len(),
        })
    }

    /// The keys the columns set.
    pub fn keys(&self) -> impl Iterator<Item = Key> + '_ {
        self.keys.iter().map(|c| c.key)
    }

    /// The parameters of one row: `base` with the row's non-empty fields.
    ///
    /// # Errors
    /// An [`InputError`] naming the column, or the row's own `error` (a failed row of the
    /// batch whose output this is).
    pub fn apply(
        &self,
        rec: &ByteRecord,
        base: &Params,
        units: Units,
    ) -> Result<Params, InputError> {
        if rec.len() != self.width {
            return Err(InputError::new(
                "input",
                format!(
                    "expected {} fields as in the header, found {}",
                    self.width,
                    rec.len()
                ),
            ));
        }
        if let Some(e) = self.error.and_then(|i| rec.get(i)) {
            let e = String::from_utf8_lossy(e);
            if !e.trim().is_empty() {
                return Err(InputError::new(
                    "input",
                    format!("the input row failed: {}", e.trim()),
                ));
            }
        }
        let mut p = *base;
        for c in &self.keys {
            let raw = rec.get(c.index).unwrap_or_default();
            let text = std::str::from_utf8(raw)
                .map_err(|_| InputError::new(c.key.name(), "is not UTF-8 text"))?;
            if text.trim().is_empty() {
                continue;
            }
            let units = if c.si { Units::Si } else { units };
            c.key.set(&mut p, units, c.key.parse(text)?);
        }
        Ok(p)
    }
}

fn line_of(rec: &ByteRecord) -> u64 {
    rec.position().map_or(0, csv::Position::line)
}

fn put_csv_text(out: &mut Vec<u8>, text: &[u8]) {
    if text
        .iter()
        .any(|b| matches!(b, b',' | b'"' | b'\n' | b'\r'))
    {
        out.push(b'"');
        for &b in text {
            if b == b'"' {
                out.push(b'"');
            }
            out.push(b);
        }
        out.push(b'"');
    } else {
        out.extend_from_slice(text);
    }
}

fn put_u64(out: &mut Vec<u8>, n: u64) {
    let _ = write!(out, "{n}");
}

/// Computes a piece of records: their rows parsed, then run together
/// ([`compute::run_rows`]: the flights in the core's lanes kernel where it covers them).
fn compute_piece(
    job: &Job,
    cols: &Columns,
    piece: &[ByteRecord],
) -> Vec<Result<report::Report, InputError>> {
    let parsed: Vec<Result<Params, InputError>> = piece
        .iter()
        .map(|rec| cols.apply(rec, &job.base, job.units))
        .collect();
    let rows: Vec<Params> = parsed
        .iter()
        .filter_map(|p| p.as_ref().ok().copied())
        .collect();
    let mut reports = compute::run_rows(job.mode, &rows, &job.numerics).into_iter();
    parsed
        .into_iter()
        .map(|p| {
            p.and_then(|_| {
                reports
                    .next()
                    .unwrap_or_else(|| Err(InputError::new("input", "row not computed")))
            })
        })
        .collect()
}

/// Formats one output row into `out` given its result; true for an error row.
fn process(
    job: &Job,
    cols: &Columns,
    rec: &ByteRecord,
    result: Result<report::Report, InputError>,
    floats: &mut Floats,
    out: &mut Vec<u8>,
) -> bool {
    let line = line_of(rec);
    let label = cols.label.and_then(|i| rec.get(i));
    let failed = result.is_err();
    if job.json {
        out.extend_from_slice(b"{\"line\":");
        put_u64(out, line);
        if let Some(l) = label {
            out.extend_from_slice(b",\"label\":");
            let _ = serde_json::to_writer(&mut *out, &String::from_utf8_lossy(l));
        }
        match result {
            Ok(r) => {
                let start = out.len();
                if serde_json::to_writer(&mut *out, &r).is_ok() && out.get(start) == Some(&b'{') {
                    out[start] = b',';
                }
            }
            Err(e) => {
                out.extend_from_slice(b",\"error\":");
                let _ =
                    serde_json::to_writer(&mut *out, &format!("line {line}: {}", e.as_column()));
                out.push(b'}');
            }
        }
        out.push(b'\n');
    } else {
        put_u64(out, line);
        if cols.label.is_some() {
            out.push(b',');
            put_csv_text(out, label.unwrap_or_default());
        }
        match result {
            Ok(r) => {
                report::write_csv_fields(out, floats, job.mode, ground_columns(job, cols), &r);
                out.extend_from_slice(b",\n");
            }
            Err(e) => {
                report::write_csv_empty(out, job.mode, ground_columns(job, cols));
                out.push(b',');
                put_csv_text(out, format!("line {line}: {}", e.as_column()).as_bytes());
                out.push(b'\n');
            }
        }
    }
    failed
}

/// Opens `input` (`-`: standard input), with its size when it is a file.
///
/// # Errors
/// A file that cannot be opened, naming `input`.
pub fn open(input: &PathBuf) -> Result<(Box<dyn Read>, Option<u64>), InputError> {
    if input.as_os_str() == "-" {
        return Ok((Box::new(std::io::stdin().lock()), None));
    }
    let f = std::fs::File::open(input)
        .map_err(|e| InputError::new("input", format!("cannot read {}: {e}", input.display())))?;
    let len = f.metadata().ok().map(|m| m.len());
    Ok((Box::new(f), len))
}

/// An opened CSV input: the reader, its column map and the file size (if known).
pub type Opened = (csv::Reader<Box<dyn Read>>, Columns, Option<u64>);

/// A CSV reader over `input` and its column map.
///
/// # Errors
/// An unreadable file or a bad header.
pub fn reader(input: &PathBuf, mode: Mode) -> Result<Opened, InputError> {
    let (file, len) = open(input)?;
    let (rdr, cols) = csv_reader(file, &input.display().to_string(), mode)?;
    Ok((rdr, cols, len))
}

/// The CSV dialect of every carry input file: a header line, rows of any length,
/// whitespace trimmed, `#` comment lines.
#[must_use]
pub fn dialect() -> csv::ReaderBuilder {
    let mut b = csv::ReaderBuilder::new();
    b.has_headers(true)
        .flexible(true)
        .trim(csv::Trim::All)
        .comment(Some(b'#'));
    b
}

/// A CSV reader over any byte source named `name` (for messages), and its column map.
///
/// # Errors
/// A missing or bad header line.
pub fn csv_reader<R: Read>(
    source: R,
    name: &str,
    mode: Mode,
) -> Result<(csv::Reader<R>, Columns), InputError> {
    let mut rdr = dialect().buffer_capacity(1 << 20).from_reader(source);
    let header = rdr
        .byte_headers()
        .map_err(|e| InputError::new("input", format!("{name}: cannot read the header: {e}")))?
        .clone();
    if header.is_empty() || (header.len() == 1 && header.get(0).is_some_and(<[u8]>::is_empty)) {
        return Err(InputError::new("input", format!("{name}: no header line")));
    }
    let cols = Columns::from_header(&header, mode)?;
    Ok((rdr, cols))
}

/// Runs a batch.
///
/// # Errors
/// A bad file or header (status 2), or failing to write the output (status 1).
pub fn run(job: &Job) -> Result<(), Failure> {
    match job.threads {
        Some(n) => {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(n)
                .build()
                .map_err(|e| InputError::new("threads", e.to_string()))?;
            pool.install(|| run_in_pool(job))
        }
        None => run_in_pool(job),
    }
}

fn run_in_pool(job: &Job) -> Result<(), Failure> {
    let (mut rdr, cols, len) = reader(&job.input, job.mode)?;
    let progress = match len {
        Some(n) if job.progress && n >= PROGRESS_BYTES && std::io::stderr().is_terminal() => {
            let bar = indicatif::ProgressBar::new(n);
            bar.set_style(
                indicatif::ProgressStyle::with_template(
                    "{bar:40} {bytes}/{total_bytes} {bytes_per_sec} eta {eta}",
                )
                .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
            );
            Some(bar)
        }
        _ => None,
    };
    let stdout = std::io::stdout();
    let mut out = std::io::BufWriter::with_capacity(1 << 20, stdout.lock());
    let (rows, errors) = stream(job, &mut rdr, &cols, &mut out, progress.as_ref())?;
    out.flush()?;
    if let Some(bar) = progress {
        bar.finish_and_clear();
    }
    if errors > 0 {
        let _ = writeln!(
            std::io::stderr(),
            "carry: {errors} of {rows} rows had errors (see their error field)"
        );
    }
    Ok(())
}

/// Runs a batch over CSV `input` bytes into `out` (no files, no threads of its own beyond
/// rayon's, no progress bar): the same parsing and formatting as `carry batch`, for fuzzing
/// and tests. Returns (rows, error rows).
///
/// # Errors
/// A bad header (status 2 in the CLI), or a write error.
pub fn run_bytes(job: &Job, input: &[u8], out: &mut Vec<u8>) -> Result<(u64, u64), Failure> {
    let (mut rdr, cols) = csv_reader(input, "input", job.mode)?;
    stream(job, &mut rdr, &cols, out, None)
}

/// Reads every record of `rdr`, computes and formats them in parallel chunks, writes the
/// header and the rows to `out` in input order. Returns (rows, error rows).
fn stream<R: Read, W: Write>(
    job: &Job,
    rdr: &mut csv::Reader<R>,
    cols: &Columns,
    out: &mut W,
    progress: Option<&indicatif::ProgressBar>,
) -> Result<(u64, u64), Failure> {
    if !job.json {
        let mut header = Vec::new();
        let prefix: &[&str] = if cols.label.is_some() {
            &["line", "label"]
        } else {
            &["line"]
        };
        report::write_csv_header(
            &mut header,
            prefix,
            job.mode,
            ground_columns(job, cols),
            &["error"],
        );
        out.write_all(&header)?;
    }
    let mut records: Vec<ByteRecord> = vec![ByteRecord::new(); CHUNK];
    let mut buffers: Vec<Vec<u8>> = vec![Vec::new(); CHUNK.div_ceil(PIECE)];
    let mut errors: u64 = 0;
    let mut rows: u64 = 0;
    loop {
        let mut n = 0;
        let mut read_error = None;
        while n < CHUNK {
            match rdr.read_byte_record(&mut records[n]) {
                Ok(true) => n += 1,
                Ok(false) => break,
                Err(e) => {
                    // A malformed record (e.g. invalid quoting): report it as an error row.
                    read_error = Some(e);
                    break;
                }
            }
        }
        // Each piece formats into its own reused buffer; written in order afterwards.
        let errors_in_chunk: u64 = records[..n]
            .par_chunks(PIECE)
            .zip(buffers.par_iter_mut())
            .map(|(piece, buf)| {
                buf.clear();
                let mut floats = Floats::default();
                let mut failed = 0;
                for (rec, result) in piece.iter().zip(compute_piece(job, cols, piece)) {
                    failed += u64::from(process(job, cols, rec, result, &mut floats, buf));
                }
                failed
            })
            .sum();
        errors += errors_in_chunk;
        for buf in &buffers[..n.div_ceil(PIECE)] {
            out.write_all(buf)?;
        }
        rows += n as u64;
        if let Some(bar) = progress {
            bar.set_position(rdr.position().byte());
        }
        if let Some(e) = read_error {
            let line = e.position().map_or(0, csv::Position::line);
            errors += 1;
            rows += 1;
            let msg = format!("line {line}: input: {e}");
            let mut buf = Vec::new();
            if job.json {
                let _ = write!(buf, "{{\"line\":{line},\"error\":");
                let _ = serde_json::to_writer(&mut buf, &msg);
                buf.extend_from_slice(b"}\n");
            } else {
                put_u64(&mut buf, line);
                if cols.label.is_some() {
                    buf.push(b',');
                }
                report::write_csv_empty(&mut buf, job.mode, ground_columns(job, cols));
                buf.push(b',');
                put_csv_text(&mut buf, msg.as_bytes());
                buf.push(b'\n');
            }
            out.write_all(&buf)?;
            if matches!(e.kind(), csv::ErrorKind::Io(_)) {
                break;
            }
            continue;
        }
        if n < CHUNK {
            break;
        }
    }
    Ok((rows, errors))
}
