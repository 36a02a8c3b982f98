//! vk.xml's dependency expressions: names of versions and extensions joined with `+`
//! (and) and `,` (or), with parentheses and a prefix `!` (not, used by
//! validusage.json's condition keys). `+` binds tighter than `,`.

use std::collections::BTreeSet;

/// Evaluate `expr` with the given names enabled. `core` is always true. A malformed
/// expression (unbalanced parentheses) evaluates what it can and never panics.
pub fn eval(expr: &str, enabled: &BTreeSet<String>) -> bool {
    let tokens = tokenize(expr);
    let mut p = Parser {
        t: &tokens,
        pos: 0,
        depth: 0,
        en: enabled,
    };
    p.or()
}

/// Nesting deeper than this (in parentheses or `!`) evaluates to false rather than
/// recursing further: real registries nest a few levels.
const MAX_DEPTH: usize = 64;

struct Parser<'a> {
    t: &'a [Tok<'a>],
    pos: usize,
    depth: usize,
    en: &'a BTreeSet<String>,
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

impl Parser<'_> {
    fn or(&mut self) -> bool {
        let mut value = self.and();
        while self.t.get(self.pos) == Some(&Tok::Or) {
            self.pos += 1;
            value |= self.and();
        }
        value
    }

    fn and(&mut self) -> bool {
        let mut value = self.atom();
        while self.t.get(self.pos) == Some(&Tok::And) {
            self.pos += 1;
            value &= self.atom();
        }
        value
    }

    fn atom(&mut self) -> bool {
        if self.depth > MAX_DEPTH {
            self.pos = self.t.len();
            return false;
        }
        let token = self.t.get(self.pos);
        self.pos += 1;
        match token {
            Some(Tok::Open) => {
                self.depth += 1;
                let v = self.or();
                self.depth -= 1;
                if self.t.get(self.pos) == Some(&Tok::Close) {
                    self.pos += 1;
                }
                v
            }
            Some(Tok::Not) => {
                self.depth += 1;
                let v = !self.atom();
                self.depth -= 1;
                v
            }
            Some(Tok::Name(n)) => *n == "core" || self.en.contains(*n),
            _ => false,
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
        let deep = format!("{}A{}", "(".repeat(100_000), ")".repeat(100_000));
        assert!(
            !eval(&deep, &set(&["A"])),
            "deep nesting gives up instead of overflowing"
        );
        // Without the depth cap this overflows the stack and aborts the test run.
        let _ = eval(&"!".repeat(100_000), &set(&[]));
    }
}
