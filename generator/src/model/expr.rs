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

/// The names an expression mentions.
pub fn names(expr: &str) -> BTreeSet<&str> {
    tokenize(expr)
        .into_iter()
        .filter_map(|t| match t {
            Tok::Name(n) => Some(n),
            _ => None,
        })
        .collect()
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

/// The minimal sets of names whose presence together makes `expr` true, where
/// `fixed` settles the names it knows (an enabled version: true; a name that cannot
/// be enabled: false) and leaves the others open. Exact, with no cap on how many
/// names take part: the expression is put in disjunctive normal form. `None` for an
/// expression with a negation (only validusage.json's condition keys have one) or
/// one that does not parse.
pub fn minimal_sets(
    expr: &str,
    fixed: &dyn Fn(&str) -> Option<bool>,
) -> Option<Vec<BTreeSet<String>>> {
    let tokens = tokenize(expr);
    let mut d = Dnf {
        t: &tokens,
        pos: 0,
        depth: 0,
        fixed,
    };
    let sets = d.or()?;
    if d.pos != tokens.len() {
        return None;
    }
    Some(minimize(sets))
}

/// Drops every set that holds another one, and duplicates.
fn minimize(mut sets: Vec<BTreeSet<String>>) -> Vec<BTreeSet<String>> {
    sets.sort_by_key(BTreeSet::len);
    let mut out: Vec<BTreeSet<String>> = Vec::new();
    for s in sets {
        if !out.iter().any(|o| o.is_subset(&s)) {
            out.push(s);
        }
    }
    out
}

struct Dnf<'a> {
    t: &'a [Tok<'a>],
    pos: usize,
    depth: usize,
    fixed: &'a dyn Fn(&str) -> Option<bool>,
}

impl Dnf<'_> {
    fn or(&mut self) -> Option<Vec<BTreeSet<String>>> {
        let mut sets = self.and()?;
        while self.t.get(self.pos) == Some(&Tok::Or) {
            self.pos += 1;
            sets.extend(self.and()?);
        }
        Some(minimize(sets))
    }

    fn and(&mut self) -> Option<Vec<BTreeSet<String>>> {
        let mut sets = self.atom()?;
        while self.t.get(self.pos) == Some(&Tok::And) {
            self.pos += 1;
            let right = self.atom()?;
            let mut product = Vec::with_capacity(sets.len() * right.len());
            for l in &sets {
                for r in &right {
                    product.push(l.union(r).cloned().collect());
                }
            }
            sets = minimize(product);
        }
        Some(sets)
    }

    fn atom(&mut self) -> Option<Vec<BTreeSet<String>>> {
        if self.depth > MAX_DEPTH {
            return None;
        }
        let token = self.t.get(self.pos);
        self.pos += 1;
        match token {
            Some(Tok::Open) => {
                self.depth += 1;
                let v = self.or()?;
                self.depth -= 1;
                (self.t.get(self.pos) == Some(&Tok::Close)).then(|| self.pos += 1)?;
                Some(v)
            }
            Some(Tok::Name(n)) => Some(match (self.fixed)(n) {
                Some(true) => vec![BTreeSet::new()],
                Some(false) => Vec::new(),
                None => vec![BTreeSet::from([n.to_string()])],
            }),
            _ => None,
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
    fn minimal_sets_are_exact_and_uncapped() {
        let open = |n: &str| match n {
            "core" | "V1" => Some(true),
            "V9" => Some(false),
            _ => None,
        };
        let sets = |e: &str| minimal_sets(e, &open).expect("parses");
        // A name is a token, not a substring: maintenance1 is not in maintenance10.
        assert_eq!(sets("maintenance10"), vec![set(&["maintenance10"])]);
        assert_eq!(sets("V1,A"), vec![set(&[])]);
        assert_eq!(sets("V9+A,B+C"), vec![set(&["B", "C"])]);
        assert_eq!(sets("(A,B)+(A,C)"), vec![set(&["A"]), set(&["B", "C"])]);
        // Twenty alternatives: the old search stopped at sixteen.
        let many: Vec<String> = (0..20).map(|i| format!("E{i}")).collect();
        assert_eq!(sets(&many.join(",")).len(), 20);
        assert_eq!(minimal_sets("!A", &open), None);
        assert_eq!(minimal_sets("(A", &open), None);
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
