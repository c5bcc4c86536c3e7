//! How an external clipper is named and started: `--external NAME=COMMAND` or a `--clippers` TOML file.

use std::path::{Path, PathBuf};

use serde::Deserialize;

use crate::cli_error::CliError;

/// One external clipper to start.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ExternalSpec {
    /// The name the harness knows it by (`--clipper NAME`, summary rows, result files).
    pub name: String,
    /// The program and its arguments, split like a shell would (no shell runs it).
    pub command: Vec<String>,
    /// Working directory of the process (default: the harness's).
    pub dir: Option<PathBuf>,
    /// The `--clippers` file it was read from, if any.
    pub file: Option<PathBuf>,
    /// The library it runs, for people (a `--clippers` file's `library`; the handshake's
    /// `name` adds the version the process found).
    pub library: Option<String>,
    /// The language the library is written in or called from (a `--clippers` file's `language`).
    pub language: Option<String>,
}

impl ExternalSpec {
    /// The option that registers it again, as a shell would need it typed: `--external
    /// 'NAME=COMMAND'`, or `--clippers FILE` for one read from a file.
    pub fn option(&self) -> String {
        let quoted = |word: &str| shlex::try_quote(word).map_or_else(|_| word.to_owned(), |q| q.into_owned());
        match &self.file {
            Some(file) => format!("--clippers {}", quoted(&file.to_string_lossy())),
            None => format!("--external {}", quoted(&format!("{}={}", self.name, shown(&self.command)))),
        }
    }
}

/// `NAME=COMMAND`, the command split into words with shell quoting rules.
pub fn parse_flag(text: &str) -> Result<ExternalSpec, CliError> {
    let Some((name, command)) = text.split_once('=') else {
        return Err(CliError::usage(format!("--external '{text}': expected NAME=COMMAND")));
    };
    let name = checked_name(name.trim()).map_err(|e| CliError::usage(format!("--external '{text}': {e}")))?;
    let command = split_command(command).map_err(|e| CliError::usage(format!("--external {name}: {e}")))?;
    Ok(ExternalSpec { name, command, dir: None, file: None, library: None, language: None })
}

/// The clippers of a TOML file: `[[clipper]]` tables with `name`, `command` and optionally
/// `dir` (relative to the file's folder), `library` and `language` (what the report's atlas says
/// it is). Unknown keys and missing commands are refused with
/// the line they are on.
pub fn parse_file(path: &Path) -> Result<Vec<ExternalSpec>, CliError> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| CliError::usage(format!("{}: cannot read it: {e}", path.display())))?;
    let mut specs = parse_toml(&text, path.parent().unwrap_or(Path::new("")))
        .map_err(|e| CliError::usage(format!("{}: {e}", path.display())))?;
    for spec in &mut specs {
        spec.file = Some(path.to_owned());
    }
    Ok(specs)
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct ClippersFile {
    clipper: Vec<ClipperTable>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct ClipperTable {
    name: toml::Spanned<String>,
    command: toml::Spanned<String>,
    #[serde(default)]
    dir: Option<String>,
    #[serde(default)]
    library: Option<String>,
    #[serde(default)]
    language: Option<String>,
}

/// [`parse_file`] on text; `base` is the folder relative `dir`s start from.
fn parse_toml(text: &str, base: &Path) -> Result<Vec<ExternalSpec>, String> {
    let file: ClippersFile = toml::from_str(text).map_err(|e| match e.span() {
        Some(span) => format!("line {}: {}", line_of(text, span.start), e.message()),
        None => e.message().to_owned(),
    })?;
    let mut specs: Vec<ExternalSpec> = Vec::new();
    for table in file.clipper {
        let at = |offset: usize| format!("line {}", line_of(text, offset));
        let name =
            checked_name(table.name.get_ref().trim()).map_err(|e| format!("{}: {e}", at(table.name.span().start)))?;
        if specs.iter().any(|s| s.name == name) {
            return Err(format!("{}: clipper '{name}' is named twice", at(table.name.span().start)));
        }
        let command =
            split_command(table.command.get_ref()).map_err(|e| format!("{}: {e}", at(table.command.span().start)))?;
        specs.push(ExternalSpec {
            name,
            command,
            dir: table.dir.map(|d| base.join(d)),
            file: None,
            library: table.library,
            language: table.language,
        });
    }
    Ok(specs)
}

/// The 1-based line holding byte `offset` of `text`.
fn line_of(text: &str, offset: usize) -> usize {
    text.as_bytes()[..offset.min(text.len())].iter().filter(|&&b| b == b'\n').count() + 1
}

/// A clipper name: non-empty, letters, digits, `-`, `_` and `.` only (it names files and folders).
fn checked_name(name: &str) -> Result<String, String> {
    if name.is_empty() {
        return Err("the clipper name is empty".into());
    }
    if let Some(c) = name.chars().find(|c| !(c.is_ascii_alphanumeric() || matches!(c, '-' | '_' | '.'))) {
        return Err(format!("clipper name '{name}' has '{c}'; use letters, digits, '-', '_' and '.'"));
    }
    Ok(name.to_owned())
}

/// A command as a shell would need it typed, for messages.
pub fn shown(command: &[String]) -> String {
    shlex::try_join(command.iter().map(String::as_str)).unwrap_or_else(|_| command.join(" "))
}

/// A command line split into words, or why it cannot be.
fn split_command(command: &str) -> Result<Vec<String>, String> {
    let words =
        shlex::split(command).ok_or_else(|| format!("cannot split the command '{command}' (unbalanced quotes?)"))?;
    if words.is_empty() {
        return Err("the command is empty".into());
    }
    Ok(words)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn flags_split_the_command_like_a_shell() {
        let s = parse_flag("shapely=python3 'my dir/clip.py' --fast").unwrap();
        assert_eq!(s.name, "shapely");
        assert_eq!(s.command, vec!["python3", "my dir/clip.py", "--fast"]);
        assert!(parse_flag("no-equals-sign").unwrap_err().message.contains("NAME=COMMAND"));
        assert!(parse_flag("a b=x").unwrap_err().message.contains("' '"));
        assert!(parse_flag("x=").unwrap_err().message.contains("empty"));
        assert!(parse_flag("x=python3 'open").unwrap_err().message.contains("quotes"));
    }

    #[test]
    fn the_option_that_registers_a_clipper_again_splits_back_to_it() {
        let s = parse_flag("shapely=python3 'my dir/clip.py' --fast").unwrap();
        let option = s.option();
        let words = shlex::split(&option).unwrap();
        assert_eq!(words[0], "--external", "{option}");
        assert_eq!(parse_flag(&words[1]).unwrap(), s);
        let mut from_file = s.clone();
        from_file.file = Some(PathBuf::from("my clippers.toml"));
        assert_eq!(shlex::split(&from_file.option()).unwrap(), ["--clippers", "my clippers.toml"]);
    }

    #[test]
    fn files_name_the_line_of_a_bad_table() {
        let good = "[[clipper]]\nname = \"mine\"\ncommand = \"./mine --json\"\ndir = \"tools\"\n";
        let specs = parse_toml(good, Path::new("/base")).unwrap();
        assert_eq!(specs[0].command, vec!["./mine", "--json"]);
        assert_eq!(specs[0].dir.as_deref(), Some(Path::new("/base/tools")));
        assert_eq!((specs[0].library.as_deref(), specs[0].language.as_deref()), (None, None));
        let described = format!("{good}library = \"Boost.Geometry\"\nlanguage = \"C++\"\n");
        let specs = parse_toml(&described, Path::new("/base")).unwrap();
        assert_eq!((specs[0].library.as_deref(), specs[0].language.as_deref()), (Some("Boost.Geometry"), Some("C++")));

        let unknown = "[[clipper]]\nname = \"mine\"\ncommand = \"./mine\"\ntimeout = 3\n";
        let e = parse_toml(unknown, Path::new("")).unwrap_err();
        assert!(e.contains("line 4") && e.contains("timeout"), "{e}");

        let missing = "[[clipper]]\nname = \"mine\"\n\n[[clipper]]\nname = \"other\"\ncommand = \"x\"\n";
        let e = parse_toml(missing, Path::new("")).unwrap_err();
        assert!(e.contains("line 1") && e.contains("command"), "{e}");

        let twice = "[[clipper]]\nname = \"a\"\ncommand = \"x\"\n[[clipper]]\nname = \"a\"\ncommand = \"y\"\n";
        assert!(parse_toml(twice, Path::new("")).unwrap_err().contains("line 5"));
    }
}
