//! vk.xml's dependency expressions: names of versions and extensions joined with `+`
//! (and) and `,` (or), with parentheses and a prefix `!` (not, used by
//! validusage.json's condition keys). `+` binds tighter than `,`.

use std::collections::BTreeSet;

/// Evaluate `expr` with the given names enabled. `core` is always true. A malformed
/// expression (unbalanced parentheses) evaluates what it can and never panics.
pub fn eval(expr: &str, enabled: &BTreeSet<String>) -> bool {
    let tokens = tokenize(expr);
    let mut pos = 0;
    parse_or(&tokens, &mut pos, enabled)
}

#[derive(Debug, PartialEq)]
enum Tok<'a> {
    Name(&'a str),
    And,
    Or,
    Not,
    Open,
    Close,
}

fn tokenize(expr: &str) -> Vec<Tok<'_>> {
    let mut out = Vec::new();
    let mut start = None;
    for (i, c) in expr.char_indices() {
        let tok = match c {
            '+' => Some(Tok::And),
            ',' => Some(Tok::Or),
            '!' => Some(Tok::Not),
            '(' => Some(Tok::Open),
            ')' => Some(Tok::Close),
            c if c.is_whitespace() => None,
            _ => {
                start.get_or_insert(i);
                continue;
            }
        };
        if let Some(s) = start.take() {
            out.push(Tok::Name(&expr[s..i]));
        }
        out.extend(tok);
    }
    if let Some(s) = start {
        out.push(Tok::Name(&expr[s..]));
    }
    out
}

fn parse_or(t: &[Tok], pos: &mut usize, en: &BTreeSet<String>) -> bool {
    let mut value = parse_and(t, pos, en);
    while t.get(*pos) == Some(&Tok::Or) {
        *pos += 1;
        value |= parse_and(t, pos, en);
    }
    value
}

fn parse_and(t: &[Tok], pos: &mut usize, en: &BTreeSet<String>) -> bool {
    let mut value = parse_atom(t, pos, en);
    while t.get(*pos) == Some(&Tok::And) {
        *pos += 1;
        value &= parse_atom(t, pos, en);
    }
    value
}

fn parse_atom(t: &[Tok], pos: &mut usize, en: &BTreeSet<String>) -> bool {
    match t.get(*pos) {
        Some(Tok::Open) => {
            *pos += 1;
            let v = parse_or(t, pos, en);
            if t.get(*pos) == Some(&Tok::Close) {
                *pos += 1;
            }
            v
        }
        Some(Tok::Not) => {
            *pos += 1;
            !parse_atom(t, pos, en)
        }
        Some(Tok::Name(n)) => {
            *pos += 1;
            *n == "core" || en.contains(*n)
        }
        _ => {
            *pos += 1;
            false
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn set(names: &[&str]) -> BTreeSet<String> {
        names.iter().map(|s| s.to_string()).collect()
    }

    #[test]
    fn and_binds_tighter_than_or() {
        let en = set(&["C"]);
        assert!(eval("A+B,C", &en));
        assert!(!eval("A+(B,C)", &en));
        assert!(eval("(A,C)+C", &en));
        assert!(eval("C+!(A,B)", &en));
        assert!(!eval("!(C)", &en));
    }

    #[test]
    fn core_is_always_true_and_garbage_is_false() {
        assert!(eval("core", &set(&[])));
        assert!(!eval("", &set(&[])));
        assert!(!eval("((,+", &set(&[])));
    }
}
