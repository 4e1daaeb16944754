//! Reading the (t, y) positions of a tracked toy from the CSV files that video-tracking apps
//! export (Tracker, Kinovea, Video Physics, Logger Pro, …).
//!
//! ```text
//! # comment lines            skipped (also anywhere below)
//! mass A                     title lines: any rows without numbers before the header
//! t,x,y                      header: the last row of names before the data
//! s,m,m                      optional units row (else units from "y (mm)" or "y [mm]")
//! 0.000,0.012,0.1043         data: from the first row with a number
//! ```
//!
//! The separator is `,`, `;` or tab, whichever most lines hold (a tie goes to `;`, then tab, so
//! that `0,5;1,2` reads as two decimal-comma numbers). Decimal commas are accepted when the
//! separator is not `,`. Quoting follows RFC 4180 (the `csv` crate).
//! A row with a blank cell in the time or the position column is skipped and counted: Tracker
//! leaves a cell blank wherever a track has no mark in a frame.
//! Every problem is one line naming the line of the file: no header, a missing column, a
//! non-numeric cell, time not strictly increasing, fewer than [`MIN_ROWS`] or more than
//! [`MAX_ROWS`] rows.

use std::path::Path;

use serde::Serialize;

use crate::error::{excerpt, short, Error, Result};

/// Longest excerpt of a cell in a message (characters).
const CELL_CHARS: usize = 40;

/// Fewest data rows a fit accepts.
pub const MIN_ROWS: usize = 10;
/// Most data rows a fit accepts (an hour of video at 30 frames per second), so that every fit
/// returns in seconds.
pub const MAX_ROWS: usize = 100_000;

/// Largest |position| read (m): a tracked toy moves by centimetres, and squares of positions
/// beyond ~1e154 m overflow the residual (RMS `inf`, autocorrelation `NaN`).
pub const MAX_POSITION_M: f64 = 1e3;

/// Unit of the position column.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, clap::ValueEnum)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
#[serde(rename_all = "lowercase")]
pub enum Unit {
    /// Metres.
    M,
    /// Centimetres.
    Cm,
    /// Millimetres.
    Mm,
}

impl Unit {
    /// Metres per unit.
    pub fn metres(self) -> f64 {
        match self {
            Unit::M => 1.0,
            Unit::Cm => 1e-2,
            Unit::Mm => 1e-3,
        }
    }

    /// The symbol, as in headers ("m", "mm").
    pub fn symbol(self) -> &'static str {
        match self {
            Unit::M => "m",
            Unit::Cm => "cm",
            Unit::Mm => "mm",
        }
    }

    fn parse(symbol: &str) -> Option<Unit> {
        match symbol {
            "m" => Some(Unit::M),
            "cm" => Some(Unit::Cm),
            "mm" => Some(Unit::Mm),
            _ => None,
        }
    }
}

/// A column chosen on the command line: a header name or a 1-based index.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Column {
    Index(usize),
    Name(String),
}

/// The two columns of `--columns T,Y`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Columns {
    pub time: Column,
    pub position: Column,
}

impl std::str::FromStr for Columns {
    type Err = String;

    /// `T,Y`: each a header name or a 1-based column number.
    fn from_str(s: &str) -> std::result::Result<Self, String> {
        let parts: Vec<&str> = s.split(',').map(str::trim).collect();
        let [time, position] = parts[..] else {
            return Err(format!(
                "'{s}': expected two columns T,Y (names or 1-based numbers)"
            ));
        };
        let column = |c: &str| match c.parse::<usize>() {
            Ok(0) => Err("column numbers start at 1".to_string()),
            Ok(i) => Ok(Column::Index(i)),
            Err(_) if c.is_empty() => Err(format!("'{s}': empty column name")),
            Err(_) => Ok(Column::Name(c.to_string())),
        };
        Ok(Columns {
            time: column(time)?,
            position: column(position)?,
        })
    }
}

/// How to read a file: the columns and the position unit when the user gave them.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ReadOptions {
    /// `None`: the first column, and the column named `y` (else the second).
    pub columns: Option<Columns>,
    /// `None`: the unit the file declares (units row or header), else metres.
    pub unit: Option<Unit>,
}

/// The tracked positions, in time order.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct Tracked {
    /// The file as given on the command line.
    pub file: String,
    /// Header names of the two columns used.
    pub time_column: String,
    pub position_column: String,
    /// Unit of the position column (the flag's, the file's, or metres).
    pub unit: Unit,
    /// Times (s) and positions as written in the file (in `unit`).
    #[serde(skip)]
    pub t: Vec<f64>,
    #[serde(skip)]
    pub y: Vec<f64>,
    /// Data rows skipped for a blank cell in the time or the position column (a frame where
    /// the track has no mark), and the line of the first.
    pub skipped_rows: usize,
    pub first_skipped_line: Option<u64>,
}

impl Tracked {
    /// Positions in metres.
    pub fn y_metres(&self) -> Vec<f64> {
        let scale = self.unit.metres();
        self.y.iter().map(|y| y * scale).collect()
    }
}

/// Reads and checks a tracked-positions file.
pub fn read(path: &Path, opts: &ReadOptions) -> Result<Tracked> {
    let bytes =
        crate::params::read_input(path, "tracked-data").map_err(|e| data_error(path, None, e))?;
    // Lossy: a Latin-1 "°" or "µ" in a header must not stop a file whose numbers are fine.
    parse(&String::from_utf8_lossy(&bytes), path, opts)
}

/// Parses the text of a tracked-positions file; `path` only names the file in errors.
pub fn parse(text: &str, path: &Path, opts: &ReadOptions) -> Result<Tracked> {
    let err = |line: Option<u64>, reason: String| data_error(path, line, reason);
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let separator = separator(text);
    let rows = records(text, separator).map_err(|(line, e)| err(line, e))?;
    let decimal_comma = separator != b',';
    let number = |cell: &str| parse_number(cell, decimal_comma);

    // The data start at the first row with a number; the rows before are the preamble.
    let first_data = rows
        .iter()
        .position(|r| r.cells.iter().any(|c| number(c).is_some()))
        .ok_or_else(|| err(None, "no data rows (no row holds a number)".to_string()))?;
    let (preamble, data) = rows.split_at(first_data);
    if let Some(row) = data.get(MAX_ROWS) {
        return Err(err(
            Some(row.line),
            format!(
                "more than {MAX_ROWS} data rows; a fit takes at most {MAX_ROWS} (keep every \
                 n-th frame)"
            ),
        ));
    }
    let header_at = preamble
        .iter()
        .rposition(|r| non_empty(&r.cells) >= 2 && !is_units_row(&r.cells))
        .ok_or_else(|| {
            err(
                Some(data[0].line),
                "no header: the data start here without a row of column names above them"
                    .to_string(),
            )
        })?;
    let header = &preamble[header_at];
    let units_row = preamble[header_at + 1..]
        .iter()
        .find(|r| is_units_row(&r.cells));
    let names: Vec<&str> = header.cells.iter().map(String::as_str).collect();
    // Two columns of one name: a name on the command line could not tell which is meant.
    for (j, name) in names.iter().enumerate() {
        let key = name.trim().to_lowercase();
        if let Some(i) = names[..j]
            .iter()
            .position(|n| !key.is_empty() && n.trim().to_lowercase() == key)
        {
            return Err(err(
                Some(header.line),
                format!(
                    "columns {} and {} are both named {}: rename one",
                    i + 1,
                    j + 1,
                    crate::error::excerpt(name.trim(), 40)
                ),
            ));
        }
    }

    let (time_col, position_col) = choose_columns(&names, opts.columns.as_ref())
        .map_err(|reason| err(Some(header.line), reason))?;
    let declared = |col: usize| {
        units_row
            .and_then(|r| r.cells.get(col))
            .map(|u| strip_brackets(u).to_string())
            .filter(|u| !u.is_empty())
            .or_else(|| unit_of_name(names[col]).map(str::to_string))
    };
    let time_scale = match declared(time_col).as_deref() {
        None | Some("s") => 1.0,
        Some("ms") => 1e-3,
        Some(other) => {
            return Err(err(
                Some(header.line),
                format!(
                    "column {} is in '{other}': times must be in s or ms",
                    names[time_col]
                ),
            ))
        }
    };
    let unit = match (opts.unit, declared(position_col)) {
        (Some(unit), _) => unit,
        (None, None) => Unit::M,
        (None, Some(symbol)) => Unit::parse(&symbol).ok_or_else(|| {
            err(
                Some(header.line),
                format!(
                    "column {} is in '{symbol}': positions must be in m, cm or mm \
                     (calibrate the video, or give --units)",
                    names[position_col]
                ),
            )
        })?,
    };

    let mut t = Vec::with_capacity(data.len());
    let mut y = Vec::with_capacity(data.len());
    let mut previous: Option<(f64, u64)> = None;
    let (mut skipped_rows, mut first_skipped_line) = (0, None);
    for row in data {
        let raw = |col: usize| row.cells.get(col).map_or("", String::as_str);
        if raw(time_col).is_empty() || raw(position_col).is_empty() {
            skipped_rows += 1;
            first_skipped_line.get_or_insert(row.line);
            continue;
        }
        let cell = |col: usize| -> Result<f64> {
            number(raw(col)).ok_or_else(|| Error::TrackedData {
                path: path.display().to_string(),
                line: Some(row.line),
                column: Some(names[col].to_string()),
                reason: format!("'{}' is not a number", excerpt(raw(col), CELL_CHARS)),
            })
        };
        let time = cell(time_col)? * time_scale;
        let position = cell(position_col)?;
        if position.abs() * unit.metres() > MAX_POSITION_M {
            return Err(Error::TrackedData {
                path: path.display().to_string(),
                line: Some(row.line),
                column: Some(names[position_col].to_string()),
                reason: format!(
                    "position {} {} is beyond {MAX_POSITION_M:e} m: a tracked toy moves by \
                     centimetres (is the column in another unit?)",
                    short(position),
                    unit.symbol()
                ),
            });
        }
        if let Some((before, line)) = previous {
            if time <= before {
                return Err(err(
                    Some(row.line),
                    format!(
                        "time not strictly increasing: {} s after {} s on line {line}",
                        short(time),
                        short(before)
                    ),
                ));
            }
        }
        previous = Some((time, row.line));
        t.push(time);
        y.push(position);
    }
    if t.len() < MIN_ROWS {
        let (first, last) = (data[0].line, data[data.len() - 1].line);
        let skipped = match skipped_rows {
            0 => String::new(),
            s => format!(" ({s} skipped for a blank cell in a used column)"),
        };
        return Err(err(
            Some(last),
            format!(
                "only {} data rows (lines {first}-{last}){skipped}; a fit needs at least \
                 {MIN_ROWS}",
                t.len()
            ),
        ));
    }
    Ok(Tracked {
        file: path.display().to_string(),
        time_column: names[time_col].to_string(),
        position_column: names[position_col].to_string(),
        unit,
        t,
        y,
        skipped_rows,
        first_skipped_line,
    })
}

fn data_error(path: &Path, line: Option<u64>, reason: String) -> Error {
    Error::TrackedData {
        path: path.display().to_string(),
        line,
        column: None,
        reason,
    }
}

/// One non-blank, non-comment row: its line number (1-based) and trimmed cells.
struct Row {
    line: u64,
    cells: Vec<String>,
}

/// The separator most lines hold; ties go to `;`, then tab, then `,`.
fn separator(text: &str) -> u8 {
    let lines: Vec<&str> = text
        .lines()
        .map(str::trim)
        .filter(|l| !l.is_empty() && !l.starts_with('#'))
        .collect();
    let count = |c: char| lines.iter().filter(|l| l.contains(c)).count();
    // In rising priority: a later candidate wins a tie.
    let mut best = (0, b',');
    for (c, byte) in [(',', b','), ('\t', b'\t'), (';', b';')] {
        let n = count(c);
        if n > 0 && n >= best.0 {
            best = (n, byte);
        }
    }
    best.1
}

/// The rows of the file (blank rows and `#` comments skipped), or (line, reason).
fn records(text: &str, separator: u8) -> std::result::Result<Vec<Row>, (Option<u64>, String)> {
    let mut reader = csv::ReaderBuilder::new()
        .has_headers(false)
        .flexible(true)
        .delimiter(separator)
        .comment(Some(b'#'))
        .trim(csv::Trim::All)
        .from_reader(text.as_bytes());
    let mut rows = Vec::new();
    for record in reader.records() {
        let record = record.map_err(|e| {
            let line = e.position().map(csv::Position::line);
            (line, e.to_string())
        })?;
        let cells: Vec<String> = record.iter().map(str::to_string).collect();
        if non_empty(&cells) == 0 {
            continue;
        }
        rows.push(Row {
            line: record.position().map_or(0, |pos| record_line(text, pos)),
            cells,
        });
    }
    Ok(rows)
}

/// The line a record is on. csv reports where it started reading, which is the first of the
/// blank and `#` comment lines it skipped before the record.
fn record_line(text: &str, pos: &csv::Position) -> u64 {
    let skipped = usize::try_from(pos.byte())
        .ok()
        .and_then(|b| text.get(b..))
        .map_or(0, |rest| {
            rest.lines()
                .take_while(|l| l.trim().is_empty() || l.starts_with('#'))
                .count()
        });
    pos.line() + skipped as u64
}

fn non_empty(cells: &[String]) -> usize {
    cells.iter().filter(|c| !c.is_empty()).count()
}

/// A finite number, with a decimal comma when allowed ("0,25" = 0.25).
fn parse_number(cell: &str, decimal_comma: bool) -> Option<f64> {
    let x = if decimal_comma && cell.matches(',').count() == 1 && !cell.contains('.') {
        cell.replace(',', ".").parse::<f64>()
    } else {
        cell.parse::<f64>()
    };
    x.ok().filter(|x| x.is_finite())
}

/// Unit spellings a units row may hold.
const UNIT_WORDS: [&str; 16] = [
    "s", "ms", "m", "cm", "mm", "px", "pixel", "pixels", "m/s", "cm/s", "mm/s", "m/s^2", "m/s²",
    "deg", "°", "rad",
];

/// A row of units under the header: every non-empty cell a unit, e.g. `s,m,m` or `(s);(mm)`.
fn is_units_row(cells: &[String]) -> bool {
    non_empty(cells) > 0
        && cells
            .iter()
            .filter(|c| !c.is_empty())
            .all(|c| UNIT_WORDS.contains(&strip_brackets(c).to_lowercase().as_str()))
}

fn strip_brackets(cell: &str) -> &str {
    cell.trim()
        .trim_start_matches(['(', '['])
        .trim_end_matches([')', ']'])
        .trim()
}

/// The unit written in a header name: "y (mm)", "y [mm]" → "mm".
fn unit_of_name(name: &str) -> Option<&str> {
    let open = name.rfind(['(', '['])?;
    let unit = strip_brackets(&name[open..]);
    (!unit.is_empty() && name.ends_with([')', ']'])).then_some(unit)
}

/// A header name without its unit, lower case: "Y (mm)" → "y".
fn bare_name(name: &str) -> String {
    let bare = match unit_of_name(name) {
        Some(_) => &name[..name.rfind(['(', '[']).unwrap_or(name.len())],
        None => name,
    };
    bare.trim().to_lowercase()
}

/// 0-based (time, position) columns from the request and the header names.
fn choose_columns(
    names: &[&str],
    request: Option<&Columns>,
) -> std::result::Result<(usize, usize), String> {
    let listing = || names.join(", ");
    let find = |c: &Column| match c {
        Column::Index(i) if *i <= names.len() => Ok(i - 1),
        Column::Index(i) => Err(format!(
            "column {i} does not exist: the header has {} columns ({})",
            names.len(),
            listing()
        )),
        Column::Name(name) => {
            let want = name.trim().to_lowercase();
            names
                .iter()
                .position(|n| n.to_lowercase() == want)
                .or_else(|| names.iter().position(|n| bare_name(n) == want))
                .ok_or_else(|| format!("no column named '{name}' in the header ({})", listing()))
        }
    };
    let (time, position) = match request {
        Some(c) => (find(&c.time)?, find(&c.position)?),
        None => {
            let y = names.iter().position(|n| bare_name(n) == "y");
            (0, y.filter(|&i| i != 0).unwrap_or(1))
        }
    };
    if time == position {
        return Err(format!(
            "time and position are the same column ({})",
            names[time]
        ));
    }
    Ok((time, position))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse_text(text: &str, opts: &ReadOptions) -> Result<Tracked> {
        parse(text, Path::new("tracked.csv"), opts)
    }

    fn rows(n: usize, line: impl Fn(usize) -> String) -> String {
        (0..n).map(|i| line(i) + "\n").collect()
    }

    fn message(text: &str) -> String {
        parse_text(text, &ReadOptions::default())
            .unwrap_err()
            .to_string()
    }

    #[test]
    fn tracker_style_file_with_title_and_y_column() {
        let text = format!(
            "mass A\nt,x,y\n{}",
            rows(12, |i| format!(
                "{},0.01,{}",
                i as f64 * 0.01,
                0.5 - i as f64 * 1e-3
            ))
        );
        let d = parse_text(&text, &ReadOptions::default()).unwrap();
        assert_eq!(
            (d.time_column.as_str(), d.position_column.as_str()),
            ("t", "y")
        );
        assert_eq!(d.unit, Unit::M);
        assert_eq!(d.t.len(), 12);
        assert_eq!(d.y[1], 0.499);
    }

    #[test]
    fn semicolons_decimal_commas_units_row_and_comments() {
        let text = format!(
            "# exported by an app\nTime;Height\ns;mm\n{}",
            rows(10, |i| format!("{},{};{},5", i, 0, 100 - i))
        );
        let d = parse_text(&text, &ReadOptions::default()).unwrap();
        assert_eq!(d.unit, Unit::Mm);
        assert_eq!(d.t[3], 3.0);
        assert_eq!(d.y[3], 97.5);
        assert_eq!(d.y_metres()[3], 0.0975);
    }

    #[test]
    fn units_in_header_names_and_columns_by_name_or_number() {
        let text = format!(
            "\"Time (s)\",\"X (m)\",\"Y (mm)\"\n{}",
            rows(10, |i| format!("{},1,{}", i, 2 * i))
        );
        let by_name = ReadOptions {
            columns: Some("time,Y".parse().unwrap()),
            unit: None,
        };
        let d = parse_text(&text, &by_name).unwrap();
        assert_eq!((d.position_column.as_str(), d.unit), ("Y (mm)", Unit::Mm));
        let by_index = ReadOptions {
            columns: Some("1,2".parse().unwrap()),
            unit: Some(Unit::Mm),
        };
        let d = parse_text(&text, &by_index).unwrap();
        assert_eq!((d.position_column.as_str(), d.unit), ("X (m)", Unit::Mm));
        assert_eq!(d.y[4], 1.0);
    }

    #[test]
    fn each_bad_file_names_the_line_and_the_problem() {
        let ok = |i: usize| format!("{}.0,{}", i, i);
        let body = |n: usize| rows(n, ok);
        let cases = [
            (body(12), "tracked.csv: line 1: no header"),
            (format!("t,y\n{}", body(7)), "line 8: only 7 data rows"),
            (
                format!("t,y\n{}1.5,abc\n{}", body(15), body(0)),
                "line 17, column y: 'abc' is not a number",
            ),
            (
                format!("t,y\n{}0.5,1\n", body(12)),
                "line 14: time not strictly increasing: 0.5 s after 11 s on line 13",
            ),
            (
                format!("t,y\n{}20,\n,5\n21\n", body(7)),
                "line 11: only 7 data rows (lines 2-11) (3 skipped for a blank cell in a used \
                 column); a fit needs at least 10",
            ),
            (
                format!("t;y (px)\n{}", rows(12, |i| format!("{i};{i}"))),
                "line 1: column y (px) is in 'px'",
            ),
            ("t,y\n".to_string(), "no data rows"),
            // Lines are counted with the comments and blank lines the reader skips.
            (
                format!("# app\n\n# units: s, m\nt,y (px)\n{}", body(12)),
                "line 4: column y (px) is in 'px'",
            ),
            (
                format!("t,y\n{}\n# paused\n\n1.5,abc\n", body(15)),
                "line 20, column y: 'abc' is not a number",
            ),
        ];
        for (text, want) in cases {
            let msg = message(&text);
            assert!(msg.contains(want), "{msg}\n  wanted: {want}");
            assert!(!msg.contains('\n'), "{msg}");
        }
        let text = format!("t,y\n{}", body(12));
        let missing = ReadOptions {
            columns: Some("t,z".parse().unwrap()),
            unit: None,
        };
        let msg = parse_text(&text, &missing).unwrap_err().to_string();
        assert!(
            msg.contains("line 1: no column named 'z' in the header (t, y)"),
            "{msg}"
        );
        let beyond = ReadOptions {
            columns: Some("1,3".parse().unwrap()),
            unit: None,
        };
        let msg = parse_text(&text, &beyond).unwrap_err().to_string();
        assert!(msg.contains("column 3 does not exist"), "{msg}");
    }

    /// Tracker leaves a cell blank in a frame where a track has no mark: such rows are skipped
    /// and counted, wherever they are; a blank in a column not used does not matter.
    #[test]
    fn rows_with_a_blank_cell_in_a_used_column_are_skipped_and_counted() {
        let text = format!(
            "mass A\nt,x,y\n,,\n0.5,,\n{}1.5,,\n2.5,1,\n,1,3\n",
            rows(12, |i| format!(
                "{},,{}",
                0.6 + i as f64 * 0.01,
                0.5 - i as f64 * 1e-3
            ))
        );
        let d = parse_text(&text, &ReadOptions::default()).unwrap();
        assert_eq!(d.t.len(), 12);
        assert_eq!((d.skipped_rows, d.first_skipped_line), (4, Some(4)));
        assert_eq!((d.t[0], d.y[11]), (0.6, 0.489));
        let whole = parse_text(
            &format!("t,y\n{}", rows(12, |i| format!("{i},{i}"))),
            &ReadOptions::default(),
        )
        .unwrap();
        assert_eq!((whole.skipped_rows, whole.first_skipped_line), (0, None));
    }

    #[test]
    fn column_requests_parse() {
        assert_eq!(
            "t, 3".parse::<Columns>().unwrap(),
            Columns {
                time: Column::Name("t".into()),
                position: Column::Index(3)
            }
        );
        assert!("t".parse::<Columns>().is_err());
        assert!("0,1".parse::<Columns>().is_err());
        assert!("t,y,z".parse::<Columns>().is_err());
    }
}
