//! Checks of WKT text before the wkt crate parses it. Its parser calls itself once per level of
//! parentheses, so a GEOMETRYCOLLECTION nested some thousands deep overflows the stack (an abort,
//! not an error): the nesting is bounded here first. And it reads `NaN` or `inf` as a word and
//! then reports a missing parenthesis: every coordinate is checked here to be a finite number,
//! and the error names it and where it is. Nor does it look past the end of the first geometry:
//! text after it is refused here rather than ignored.

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

/// Checks `text` for what the wkt crate would crash on or misreport.
pub fn check(text: &str) -> Result<(), String> {
    let mut depth = 0usize;
    // Set when the geometry's outer parentheses close, or at `EMPTY` outside them.
    let mut ended = false;
    for token in tokens(text) {
        if ended {
            return Err(format!(
                "text after the end of the geometry ({}): '{}' (a WKT file holds one geometry; put several in a \
                 GEOMETRYCOLLECTION)",
                token.at(),
                token.text
            ));
        }
        match token.text {
            "(" => {
                depth += 1;
                if depth > MAX_DEPTH {
                    return Err(format!("parentheses nested deeper than {MAX_DEPTH} levels ({})", token.at()));
                }
            }
            ")" => {
                depth = depth.saturating_sub(1);
                ended = depth == 0;
            }
            word if depth == 0 && word.eq_ignore_ascii_case("EMPTY") => ended = true,
            "," => {}
            word if depth > 0 && is_number_like(word) => match word.parse::<f64>() {
                Ok(v) if v.is_finite() => {}
                Ok(_) => return Err(format!("coordinate '{word}' ({}) is not finite", token.at())),
                Err(_) => return Err(format!("coordinate '{word}' ({}) is not a number", token.at())),
            },
            _ => {}
        }
    }
    Ok(())
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
