//! Checks of WKT text before the wkt crate parses it. Its parser calls itself once per level of
//! parentheses, so a GEOMETRYCOLLECTION nested some thousands deep overflows the stack (an abort,
//! not an error): the nesting is bounded here first. And it reads `NaN` or `inf` as a word and
//! then reports a missing parenthesis: every coordinate is checked here to be a finite number,
//! and the error names it and where it is. Nor does it look past the end of the first geometry:
//! text after it is refused here rather than ignored. Its other messages name no place ("Invalid
//! WKT format", "Missing closing parenthesis for type"): an empty file, a word that is no
//! geometry type, a character that is not ASCII, a position of too many numbers and a parenthesis
//! never closed are named here with their line and column.

/// The deepest nesting of parentheses read: a MULTIPOLYGON's coordinates are 3 deep and each
/// GEOMETRYCOLLECTION around it adds one, so this leaves room for any real file while staying
/// far from the depth (some thousands) at which the parser's recursion overflows the stack.
pub const MAX_DEPTH: usize = 256;

/// A token of WKT text (a parenthesis, a comma, or a word or number) and where it starts.
struct Token<'a> {
    text: &'a str,
    line: usize,
    column: usize,
}

impl Token<'_> {
    /// Where the token is: `line 2, column 14`.
    fn at(&self) -> String {
        format!("line {}, column {}", self.line, self.column)
    }
}

/// The geometry types the wkt crate reads.
const TYPES: [&str; 7] =
    ["POINT", "LINESTRING", "POLYGON", "MULTIPOINT", "MULTILINESTRING", "MULTIPOLYGON", "GEOMETRYCOLLECTION"];

/// Numbers a WKT position may hold: x y, then z and m.
const POSITION_NUMBERS: std::ops::RangeInclusive<usize> = 2..=4;

/// Checks `text` for what the wkt crate would crash on or misreport.
pub fn check(text: &str) -> Result<(), String> {
    for (n, line) in text.lines().enumerate().filter(|_| !text.is_ascii()) {
        if let Some((i, c)) = line.char_indices().find(|(_, c)| !c.is_ascii()) {
            let what = if c == '\u{feff}' { "a byte order mark".to_owned() } else { format!("'{c}'") };
            let column = line[..i].chars().count() + 1;
            return Err(format!("{what} (line {}, column {column}) is not ASCII: WKT is written in ASCII", n + 1));
        }
    }
    let mut depth = 0usize;
    // Set when the geometry's outer parentheses close, or at `EMPTY` outside them.
    let mut ended = false;
    // Where each open parenthesis is, innermost last.
    let mut open: Vec<String> = Vec::new();
    // The numbers of the position being read, and where it starts.
    let mut position: (usize, String) = (0, String::new());
    let mut first = true;
    for token in tokens(text) {
        if first {
            first = false;
            let word = token.text.trim_end_matches(['Z', 'z', 'M', 'm']);
            let known = |w: &str| TYPES.iter().any(|t| t.eq_ignore_ascii_case(w));
            if !known(token.text) && !known(word) {
                return Err(format!(
                    "'{}' ({}) is not a WKT geometry type ({})",
                    token.text,
                    token.at(),
                    TYPES.join(", ")
                ));
            }
        }
        if ended {
            return Err(format!(
                "text after the end of the geometry ({}): '{}' (a WKT file holds one geometry; put several in a \
                 GEOMETRYCOLLECTION)",
                token.at(),
                token.text
            ));
        }
        if matches!(token.text, "(" | ")" | ",") {
            check_position(&position)?;
            position = (0, String::new());
        }
        match token.text {
            "(" => {
                depth += 1;
                if depth > MAX_DEPTH {
                    return Err(format!("parentheses nested deeper than {MAX_DEPTH} levels ({})", token.at()));
                }
                open.push(token.at());
            }
            ")" => {
                depth = depth.saturating_sub(1);
                open.pop();
                ended = depth == 0;
            }
            word if depth == 0 && word.eq_ignore_ascii_case("EMPTY") => ended = true,
            "," => {}
            word if depth > 0 && is_number_like(word) => {
                match word.parse::<f64>() {
                    Ok(v) if v.is_finite() => {}
                    Ok(_) => return Err(format!("coordinate '{word}' ({}) is not finite", token.at())),
                    Err(_) => return Err(format!("coordinate '{word}' ({}) is not a number", token.at())),
                }
                if position.0 == 0 {
                    position.1 = token.at();
                }
                position.0 += 1;
            }
            _ => {}
        }
    }
    if first {
        return Err("it is empty: a WKT file holds one geometry".into());
    }
    if let Some(at) = open.last() {
        return Err(format!("the '(' at {at} is never closed: a ')' is missing"));
    }
    Ok(())
}

/// A position's count of numbers (`count`, starting at `at`), which must be 2 to 4 when any.
fn check_position((count, at): &(usize, String)) -> Result<(), String> {
    if *count == 0 || POSITION_NUMBERS.contains(count) {
        return Ok(());
    }
    Err(format!(
        "the position at {at} has {count} number{}: a WKT position has 2 to 4 (x y, then z and m)",
        if *count == 1 { "" } else { "s" }
    ))
}

/// `text` with every `()` (an empty ring or line string, as some writers put it) written as
/// `EMPTY`, which the wkt crate reads; run on text [`check`] passed.
pub fn empty_parentheses_as_empty(text: &str) -> std::borrow::Cow<'_, str> {
    let mut out = String::new();
    let mut copied = 0;
    let mut previous: Option<Token<'_>> = None;
    for token in tokens(text) {
        if let Some(p) = &previous
            && p.text == "("
            && token.text == ")"
        {
            let start = p.text.as_ptr() as usize - text.as_ptr() as usize;
            let end = token.text.as_ptr() as usize - text.as_ptr() as usize + 1;
            out.push_str(&text[copied..start]);
            out.push_str(" EMPTY ");
            copied = end;
        }
        previous = Some(token);
    }
    if copied == 0 {
        return std::borrow::Cow::Borrowed(text);
    }
    out.push_str(&text[copied..]);
    std::borrow::Cow::Owned(out)
}

/// A word meant as a number: one the wkt crate reads as a number (it starts with a digit, `.`,
/// `+` or `-`) or a name of a value that is not finite (`NaN`, `inf`, `infinity`, signed or not).
fn is_number_like(word: &str) -> bool {
    let unsigned = word.trim_start_matches(['+', '-']);
    word.starts_with(|c: char| c.is_ascii_digit() || matches!(c, '.' | '+' | '-'))
        || ["nan", "inf", "infinity"].iter().any(|name| unsigned.eq_ignore_ascii_case(name))
}

/// The tokens of `text` as the wkt crate splits it: at spaces, tabs and line ends, and around `(`,
/// `)` and `,`.
fn tokens(text: &str) -> impl Iterator<Item = Token<'_>> {
    let mut chars = text.char_indices().peekable();
    // Where the next character is; counted as we go (files of 10^6 vertices are one line).
    let (mut line, mut column) = (1, 1);
    let is_mark = |c: char| matches!(c, '(' | ')' | ',');
    let is_space = |c: char| matches!(c, ' ' | '\n' | '\r' | '\t');
    std::iter::from_fn(move || {
        loop {
            let (start, c) = chars.next()?;
            let at = (line, column);
            (line, column) = if c == '\n' { (line + 1, 1) } else { (line, column + 1) };
            if is_space(c) {
                continue;
            }
            let mut end = start + c.len_utf8();
            if !is_mark(c) {
                while let Some(&(i, next)) = chars.peek() {
                    if is_space(next) || is_mark(next) {
                        break;
                    }
                    (end, column) = (i + next.len_utf8(), column + 1);
                    chars.next();
                }
            }
            return Some(Token { text: &text[start..end], line: at.0, column: at.1 });
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wkt_nested_deeper_than_the_limit_is_an_error_not_a_stack_overflow() {
        let nested = |n: usize| format!("{}POINT(1 2){}", "GEOMETRYCOLLECTION(".repeat(n), ")".repeat(n));
        assert!(check(&nested(MAX_DEPTH - 1)).is_ok());
        let problem = check(&nested(8000)).unwrap_err();
        // The 257th `(`, each the 19th character of `GEOMETRYCOLLECTION(`.
        assert_eq!(problem, "parentheses nested deeper than 256 levels (line 1, column 4883)");
    }

    #[test]
    fn wkt_nan_coordinate_is_named_with_its_line_and_column() {
        assert_eq!(
            check("POLYGON((0 0,NaN 0,1 1,0 0))").unwrap_err(),
            "coordinate 'NaN' (line 1, column 14) is not finite"
        );
        assert_eq!(
            check("POLYGON((0 0,\n1 -inf,1 1,0 0))").unwrap_err(),
            "coordinate '-inf' (line 2, column 3) is not finite"
        );
        assert_eq!(
            check("LINESTRING(0 0,1e999 1)").unwrap_err(),
            "coordinate '1e999' (line 1, column 16) is not finite"
        );
        assert_eq!(check("LINESTRING(0 0,1x 1)").unwrap_err(), "coordinate '1x' (line 1, column 16) is not a number");
        // Words that are not numbers (types, Z, EMPTY) are the parser's to judge.
        assert!(check("GEOMETRYCOLLECTION(POLYGON Z((0 0 1,1 0 1,1 1 1,0 0 1)),POINT EMPTY)").is_ok());
    }

    #[test]
    fn wkt_text_after_the_geometry_is_an_error() {
        let after = |text| check(text).unwrap_err();
        assert_eq!(
            after("POLYGON((0 0,1 0,1 1,0 0)) garbage"),
            "text after the end of the geometry (line 1, column 28): 'garbage' (a WKT file holds one geometry; \
             put several in a GEOMETRYCOLLECTION)"
        );
        assert!(
            after("POLYGON((0 0,1 0,1 1,0 0)))")
                .starts_with("text after the end of the geometry (line 1, column 27): ')'")
        );
        assert!(
            after("POINT(1 2)\nPOINT(3 4)")
                .starts_with("text after the end of the geometry (line 2, column 1): 'POINT'")
        );
        assert!(
            after("MULTIPOLYGON EMPTY, 5").starts_with("text after the end of the geometry (line 1, column 19): ','")
        );
        // White space after the end is fine, and so is EMPTY inside a collection.
        assert!(check("GEOMETRYCOLLECTION(POINT EMPTY, POLYGON EMPTY)\n\n").is_ok());
    }

    #[test]
    fn tokens_split_like_the_wkt_crate_and_know_their_line_and_column() {
        let found: Vec<(&str, usize, usize)> =
            tokens("POLYGON Z((0 0 1,\n  1e3 -2 NaN))").map(|t| (t.text, t.line, t.column)).collect();
        assert_eq!(
            found,
            [
                ("POLYGON", 1, 1),
                ("Z", 1, 9),
                ("(", 1, 10),
                ("(", 1, 11),
                ("0", 1, 12),
                ("0", 1, 14),
                ("1", 1, 16),
                (",", 1, 17),
                ("1e3", 2, 3),
                ("-2", 2, 7),
                ("NaN", 2, 10),
                (")", 2, 13),
                (")", 2, 14),
            ]
        );
    }
}
