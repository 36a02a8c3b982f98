//! vk.xml's dependency expressions: names of versions and extensions joined with `+`
//! (and) and `,` (or), with parentheses and a prefix `!` (not, used by
//! validusage.json's condition keys). `+` binds tighter than `,`.

use std::collections::BTreeSet;

/// A parsed dependency expression. `core` is a name that is always true.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Expr {
    /// A version or extension name (or `core`).
    Name(String),
    /// Every operand holds (`+`).
    All(Vec<Expr>),
    /// Some operand holds (`,`).
    Any(Vec<Expr>),
    /// The operand does not hold (`!`, validusage.json's keys only).
    Not(Box<Expr>),
}

impl Expr {
    /// Parse an expression, or say where it is malformed.
    pub fn parse(text: &str) -> Result<Expr, String> {
        let tokens = tokenize(text);
        let mut p = Tree {
            t: &tokens,
            pos: 0,
            depth: 0,
        };
        let e = p.or()?;
        match tokens.get(p.pos) {
            None => Ok(e),
            Some(t) => Err(format!("unexpected {t:?} at token {}", p.pos + 1)),
        }
    }

    /// Whether the expression holds with the given names enabled.
    pub fn eval(&self, enabled: &BTreeSet<String>) -> bool {
        match self {
            Expr::Name(n) => n == "core" || enabled.contains(n),
            Expr::All(v) => v.iter().all(|e| e.eval(enabled)),
            Expr::Any(v) => v.iter().any(|e| e.eval(enabled)),
            Expr::Not(e) => !e.eval(enabled),
        }
    }

    /// Whether the expression can hold for a program that enables some of `allowed`:
    /// any extension may be left off (`!X` can hold while `X` is allowed), every
    /// allowed core version is on. Names that occur twice are taken apart, which can
    /// only answer yes more often.
    pub fn may_hold(&self, allowed: &BTreeSet<String>) -> bool {
        self.can(true, allowed)
    }

    fn can(&self, value: bool, allowed: &BTreeSet<String>) -> bool {
        match (self, value) {
            (Expr::Name(n), true) => n == "core" || allowed.contains(n),
            // A core version the program may enable is taken as enabled: the
            // wrappers read rules as for the newest version they emit.
            (Expr::Name(n), false) => {
                n != "core" && !(n.starts_with("VK_VERSION_") && allowed.contains(n))
            }
            (Expr::All(v), true) | (Expr::Any(v), false) => v.iter().all(|e| e.can(value, allowed)),
            (Expr::All(v), false) | (Expr::Any(v), true) => v.iter().any(|e| e.can(value, allowed)),
            (Expr::Not(e), _) => e.can(!value, allowed),
        }
    }

    /// The same expression with nested operands of the same kind flattened
    /// (`A,(B,A)` is `A,B,A`), repeated operands dropped (`A,B`) and a lone operand
    /// standing for its group: validusage.json's keys repeat the version a rule's
    /// item belongs to inside the alternatives of its extension.
    pub fn simplified(&self) -> Expr {
        match self {
            Expr::Name(_) => self.clone(),
            Expr::Not(e) => Expr::Not(Box::new(e.simplified())),
            Expr::All(v) | Expr::Any(v) => {
                let any = matches!(self, Expr::Any(_));
                let mut flat: Vec<Expr> = Vec::new();
                for e in v.iter().map(Expr::simplified) {
                    let inner = match (&e, any) {
                        (Expr::Any(w), true) | (Expr::All(w), false) => w.clone(),
                        _ => vec![e],
                    };
                    for e in inner {
                        if !flat.contains(&e) {
                            flat.push(e);
                        }
                    }
                }
                match (flat.len(), any) {
                    (1, _) => flat.pop().expect("one operand"),
                    (_, true) => Expr::Any(flat),
                    (_, false) => Expr::All(flat),
                }
            }
        }
    }

    /// The names the expression mentions.
    pub fn names(&self) -> BTreeSet<&str> {
        let mut out = BTreeSet::new();
        self.collect_names(&mut out);
        out
    }

    fn collect_names<'a>(&'a self, out: &mut BTreeSet<&'a str>) {
        match self {
            Expr::Name(n) => {
                out.insert(n.as_str());
            }
            Expr::All(v) | Expr::Any(v) => v.iter().for_each(|e| e.collect_names(out)),
            Expr::Not(e) => e.collect_names(out),
        }
    }

    /// The top-level alternatives: the operands of an `Any`, else the expression.
    pub fn alternatives(&self) -> &[Expr] {
        match self {
            Expr::Any(v) => v,
            other => std::slice::from_ref(other),
        }
    }

    /// The name an alternative starts with (`VK_KHR_a` for `VK_KHR_a+VK_KHR_b`).
    pub fn first_name(&self) -> Option<&str> {
        match self {
            Expr::Name(n) => Some(n),
            Expr::All(v) | Expr::Any(v) => v.first().and_then(Expr::first_name),
            Expr::Not(_) => None,
        }
    }

    /// The minimal sets of names whose presence together makes the expression true,
    /// where `fixed` settles the names it knows (an enabled version: true; a name
    /// that cannot be enabled: false) and leaves the others open. Exact, with no cap
    /// on how many names take part (the disjunctive normal form). `None` when the
    /// expression has a negation.
    pub fn minimal_sets(
        &self,
        fixed: &dyn Fn(&str) -> Option<bool>,
    ) -> Option<Vec<BTreeSet<String>>> {
        Some(match self {
            Expr::Name(n) => match fixed(n) {
                Some(true) => vec![BTreeSet::new()],
                Some(false) => Vec::new(),
                None => vec![BTreeSet::from([n.clone()])],
            },
            Expr::Any(v) => {
                let mut sets = Vec::new();
                for e in v {
                    sets.extend(e.minimal_sets(fixed)?);
                }
                minimize(sets)
            }
            Expr::All(v) => {
                let mut sets = vec![BTreeSet::new()];
                for e in v {
                    let right = e.minimal_sets(fixed)?;
                    let mut product = Vec::with_capacity(sets.len() * right.len());
                    for l in &sets {
                        for r in &right {
                            product.push(l.union(r).cloned().collect());
                        }
                    }
                    sets = minimize(product);
                }
                sets
            }
            Expr::Not(_) => return None,
        })
    }
}

/// [`Expr::may_hold`] over the text of an expression; a malformed one may hold.
pub fn may_hold(expr: &str, allowed: &BTreeSet<String>) -> bool {
    Expr::parse(expr).map_or(true, |e| e.may_hold(allowed))
}

/// Evaluate the text of an expression with the given names enabled; a malformed
/// expression is false.
pub fn eval(expr: &str, enabled: &BTreeSet<String>) -> bool {
    Expr::parse(expr).is_ok_and(|e| e.eval(enabled))
}

/// [`Expr::minimal_sets`] of the text of an expression; `None` when it does not
/// parse or has a negation.
pub fn minimal_sets(
    expr: &str,
    fixed: &dyn Fn(&str) -> Option<bool>,
) -> Option<Vec<BTreeSet<String>>> {
    Expr::parse(expr).ok()?.minimal_sets(fixed)
}

/// Nesting deeper than this (in parentheses or `!`) is refused rather than recursed
/// into: real registries nest a few levels.
const MAX_DEPTH: usize = 64;

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

/// The parser: `,` over `+` over atoms (a name, a parenthesised expression, `!`).
struct Tree<'a> {
    t: &'a [Tok<'a>],
    pos: usize,
    depth: usize,
}

impl Tree<'_> {
    fn or(&mut self) -> Result<Expr, String> {
        let mut v = vec![self.and()?];
        while self.t.get(self.pos) == Some(&Tok::Or) {
            self.pos += 1;
            v.push(self.and()?);
        }
        Ok(if v.len() == 1 {
            v.remove(0)
        } else {
            Expr::Any(v)
        })
    }

    fn and(&mut self) -> Result<Expr, String> {
        let mut v = vec![self.atom()?];
        while self.t.get(self.pos) == Some(&Tok::And) {
            self.pos += 1;
            v.push(self.atom()?);
        }
        Ok(if v.len() == 1 {
            v.remove(0)
        } else {
            Expr::All(v)
        })
    }

    fn atom(&mut self) -> Result<Expr, String> {
        if self.depth > MAX_DEPTH {
            return Err(format!("nested deeper than {MAX_DEPTH} levels"));
        }
        let token = self.t.get(self.pos);
        self.pos += 1;
        match token {
            Some(Tok::Open) => {
                self.depth += 1;
                let v = self.or()?;
                self.depth -= 1;
                if self.t.get(self.pos) != Some(&Tok::Close) {
                    return Err(format!("`(` without `)` before token {}", self.pos + 1));
                }
                self.pos += 1;
                Ok(v)
            }
            Some(Tok::Not) => {
                self.depth += 1;
                let v = self.atom()?;
                self.depth -= 1;
                Ok(Expr::Not(Box::new(v)))
            }
            Some(Tok::Name(n)) => Ok(Expr::Name((*n).to_owned())),
            Some(t) => Err(format!("unexpected {t:?} at token {}", self.pos)),
            None => Err("the expression ends where a name is expected".into()),
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
    fn simplified_flattens_and_drops_repeats_without_changing_the_value() {
        let simple = |e: &str| Expr::parse(e).expect("parses").simplified();
        let p = |e: &str| Expr::parse(e).expect("parses");
        assert_eq!(simple("V13,(SYNC2,V13)"), p("V13,SYNC2"));
        assert_eq!(simple("(A+B)+(B+C)"), p("A+B+C"));
        assert_eq!(simple("(A,A)+B"), p("A+B"));
        assert_eq!(simple("!((A,A))"), p("!(A)"));
        // Groups of the other kind stay whole.
        assert_eq!(simple("A,(B+A)"), p("A,B+A"));
        for e in [
            "V13,(SYNC2,V13)",
            "(A+B)+(B+C)",
            "A,(B+A),!(C,C)",
            "(A,(B,(C+D)))+A",
        ] {
            let (before, after) = (p(e), simple(e));
            for bits in 0..64u32 {
                let en: BTreeSet<String> = ["A", "B", "C", "D", "V13", "SYNC2"]
                    .iter()
                    .enumerate()
                    .filter(|(i, _)| bits & (1 << i) != 0)
                    .map(|(_, n)| n.to_string())
                    .collect();
                assert_eq!(before.eval(&en), after.eval(&en), "{e} with {en:?}");
            }
        }
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
    fn parses_once_into_a_tree() {
        let e = Expr::parse("VK_KHR_a+VK_KHR_b,(VK_VERSION_1_1)").expect("parses");
        let name = |n: &str| Expr::Name(n.to_owned());
        assert_eq!(
            e,
            Expr::Any(vec![
                Expr::All(vec![name("VK_KHR_a"), name("VK_KHR_b")]),
                name("VK_VERSION_1_1"),
            ])
        );
        assert_eq!(e.alternatives().len(), 2);
        assert_eq!(e.alternatives()[0].first_name(), Some("VK_KHR_a"));
        assert_eq!(e.names().len(), 3);
        assert!(e.eval(&set(&["VK_VERSION_1_1"])));
        assert!(!e.eval(&set(&["VK_KHR_a"])));
        for bad in ["", "(A", "A)", "A+", ",A", "A B("] {
            assert!(Expr::parse(bad).is_err(), "{bad:?} parsed");
        }
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
