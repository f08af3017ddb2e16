//! The one error type of every reader: what is wrong, and where.

/// A malformed input: 1-based `line` and `column` (in characters) of the offending text, and
/// what is wrong there.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("line {line}, column {column}: {message}")]
pub struct ParseError {
    /// 1-based line of the offending text.
    pub line: usize,
    /// 1-based column (in characters) of the offending text within its line.
    pub column: usize,
    /// What is wrong there.
    pub message: String,
}

/// A set that a writer cannot spell in the asked format and number style, and why.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{0}")]
pub struct WriteError(pub String);

impl ParseError {
    /// The error `message` at byte `offset` of `text`.
    pub(crate) fn at(text: &str, offset: usize, message: impl Into<String>) -> ParseError {
        let (line, column) = line_column(text, offset);
        ParseError {
            line,
            column,
            message: message.into(),
        }
    }

    /// The error `message` at `token`, a subslice of `text`.
    pub(crate) fn at_token(text: &str, token: &str, message: impl Into<String>) -> ParseError {
        let offset = (token.as_ptr() as usize).saturating_sub(text.as_ptr() as usize);
        ParseError::at(text, offset, message)
    }
}

/// The 1-based line and column (in characters) of byte `offset` of `text`, clamped to its end.
pub(crate) fn line_column(text: &str, offset: usize) -> (usize, usize) {
    let mut end = offset.min(text.len());
    while !text.is_char_boundary(end) {
        end -= 1;
    }
    let before = &text[..end];
    let line_start = before.rfind('\n').map_or(0, |i| i + 1);
    (
        before.matches('\n').count() + 1,
        before[line_start..].chars().count() + 1,
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn positions_are_one_based_characters() {
        let text = "ab\ncé d";
        assert_eq!(
            ParseError::at(text, 0, "m").to_string(),
            "line 1, column 1: m"
        );
        let e = ParseError::at(text, text.find('d').unwrap(), "bad");
        assert_eq!((e.line, e.column), (2, 4));
        assert_eq!(ParseError::at(text, 999, "m").column, 5);
    }
}
