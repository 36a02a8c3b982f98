//! The recogniser pass: reads each explicit rule's text and turns the phrasings it
//! understands into a typed check ([`Check`]) over the members of the rule's struct.
//!
//! Each recogniser is one phrasing of the specification, mined from the rule texts
//! (the ones that cover the most rules first) and listed in [`RECOGNISERS`]; the
//! report counts how many rules each one reads. A rule is recognised only when every
//! name it mentions resolves in the model (a member of the struct, a value of that
//! member's enum or flags type, a Vulkan 1.0 feature, a device limit), so a check
//! never guesses.

use crate::model::{Kind, Model};
use regex::Regex;
use std::sync::OnceLock;

mod requirements;

use requirements::*;
pub use requirements::{core_feature, is_bool, number, numeric, unsigned, CORE_FEATURES};

/// A rule the recognisers read: a check of the members of its struct.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Recognised {
    /// The rule.
    pub vuid: String,
    /// The struct it is about.
    pub item: String,
    /// The recogniser that read it.
    pub by: &'static str,
    /// The rule as one line of plain text.
    pub text: String,
    /// The item is a command, whose parameters the paths name (rather than a
    /// struct's members).
    pub on_command: bool,
    /// What the rule asks.
    pub check: Check,
    /// The condition validusage.json files the rule under, where it names an
    /// extension: the check runs only where that condition holds.
    pub key: Option<String>,
}

/// A rule as a check: when every `when` holds, `must` must hold (for each element
/// of an array, when the rule is about its elements).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Check {
    /// The conditions under which the rule applies.
    pub when: Vec<Pred>,
    /// What must hold.
    pub must: Pred,
    /// The array whose every element the rule is about; the element's members are
    /// written `array[].member` in the predicates' paths.
    pub each: Option<Each>,
}

/// An array of structs a rule reads element by element.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Each {
    /// The array: a command's slice parameter or a struct's pointer member.
    pub array: String,
    /// The member holding its length, for a struct's array (a command's slice
    /// carries its own).
    pub count: Option<String>,
}

/// One value of an enum or bit of a flags type, by its registry name.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Value {
    /// `VK_...`.
    pub name: String,
    /// Its number (the bit's value, for a flag).
    pub number: i64,
}

/// A comparison.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Op {
    /// `<`.
    Lt,
    /// `<=`.
    Le,
    /// `>`.
    Gt,
    /// `>=`.
    Ge,
    /// `==`.
    Eq,
    /// `!=`.
    Ne,
}

/// An object whose creation parameters the device records, named by a handle
/// member or parameter.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Object {
    /// A `VkBuffer`.
    Buffer,
    /// A `VkImage`.
    Image,
}

impl Object {
    fn of(c_type: &str) -> Option<Object> {
        match c_type {
            "VkBuffer" => Some(Object::Buffer),
            "VkImage" => Some(Object::Image),
            _ => None,
        }
    }

    /// The registry's name of its usage bits.
    pub fn usage_bits(self) -> &'static str {
        match self {
            Object::Buffer => "VkBufferUsageFlagBits",
            Object::Image => "VkImageUsageFlagBits",
        }
    }
}

/// The right-hand side of a comparison.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Rhs {
    /// A number, as the text writes it.
    Const(String),
    /// Another member of the same struct.
    Member(String),
    /// A member of `VkPhysicalDeviceLimits`.
    Limit(String),
    /// A creation parameter of the object a handle names, as the device recorded
    /// it (`size` of a buffer, `mipLevels` of an image).
    Created {
        /// The handle's path.
        handle: String,
        /// What it names.
        object: Object,
        /// The creation parameter, as the registry names it.
        field: String,
    },
    /// The width, height or depth of one mip level of the image a handle names:
    /// the recorded extent shifted right by the level, at least 1.
    Extent {
        /// The image handle's path.
        handle: String,
        /// `width`, `height` or `depth`.
        dim: String,
        /// The path of the mip level.
        level: String,
    },
}

/// A predicate over the struct's members and the device.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Pred {
    /// A flags member has at least one of these bits set.
    AnyBit {
        /// The member.
        member: String,
        /// The bits.
        bits: Vec<Value>,
    },
    /// A flags member has none of these bits set.
    NoBit {
        /// The member.
        member: String,
        /// The bits.
        bits: Vec<Value>,
    },
    /// An enum member is one of these values.
    OneOf {
        /// The member.
        member: String,
        /// The values.
        values: Vec<Value>,
    },
    /// An enum member is none of these values.
    NoneOf {
        /// The member.
        member: String,
        /// The values.
        values: Vec<Value>,
    },
    /// A numeric member (or the sum of two) compared with a constant, another
    /// member, a limit or what the device recorded of an object.
    Compare {
        /// The member.
        member: String,
        /// A second member added to the first (`baseArrayLayer + layerCount`).
        plus: Option<String>,
        /// How.
        op: Op,
        /// With what.
        rhs: Rhs,
        /// Compared as floating-point numbers (one side is a `float`).
        float: bool,
        /// The member is an unsigned integer.
        unsigned: bool,
    },
    /// The absolute value of a number member is at most a limit.
    AbsAtMost {
        /// The member.
        member: String,
        /// The limit ([`Rhs::Limit`]).
        rhs: Rhs,
    },
    /// A whole-number member is a multiple of a constant or a limit.
    MultipleOf {
        /// The member.
        member: String,
        /// Of what: [`Rhs::Const`] or [`Rhs::Limit`].
        rhs: Rhs,
    },
    /// The object a handle names was created with every one of these usage bits.
    Usage {
        /// The handle's path.
        handle: String,
        /// What it names.
        object: Object,
        /// The bits.
        bits: Vec<Value>,
    },
    /// The object a handle names has memory bound, or was created sparse.
    Bound {
        /// The handle's path.
        handle: String,
        /// What it names.
        object: Object,
    },
    /// A core feature (a member of `VkPhysicalDeviceFeatures` or of a core
    /// version's features struct) is enabled on the device.
    Feature {
        /// The feature.
        name: String,
        /// Which core version's features hold it (`v10` to `v13`).
        core: &'static str,
        /// Enabled rather than not.
        enabled: bool,
    },
    /// The image a handle names was created with one of these `VkImageType`s.
    ImageType {
        /// The handle's path.
        handle: String,
        /// The types.
        values: Vec<Value>,
    },
    /// A `VkFormat` member names a format of this kind (by its components, from the
    /// registry's `<formats>`).
    FormatIs {
        /// The member.
        member: String,
        /// The kind.
        class: FormatClass,
    },
    /// An aspect mask names only aspects that the format of the image a handle
    /// names has.
    AspectsIn {
        /// The aspect mask's path.
        member: String,
        /// The image handle's path.
        handle: String,
    },
    /// Every one of these holds (`x and (y + x) must both be ...`).
    All(Vec<Pred>),
}

/// A kind of format, by the aspects its components give it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FormatClass {
    /// Neither depth nor stencil.
    Color,
    /// Depth, stencil or both.
    DepthStencil,
    /// Depth and no stencil.
    DepthOnly,
    /// Stencil and no depth.
    StencilOnly,
    /// Depth and stencil.
    DepthAndStencil,
    /// A color or a depth aspect.
    ColorOrDepth,
    /// A stencil aspect.
    Stencil,
}

impl FormatClass {
    /// Whether a format with these aspect bits (COLOR 1, DEPTH 2, STENCIL 4) is of
    /// the kind.
    pub fn holds(self, color: bool, depth: bool, stencil: bool) -> bool {
        match self {
            FormatClass::Color => !depth && !stencil,
            FormatClass::DepthStencil => depth || stencil,
            FormatClass::DepthOnly => depth && !stencil,
            FormatClass::StencilOnly => stencil && !depth,
            FormatClass::DepthAndStencil => depth && stencil,
            FormatClass::ColorOrDepth => color || depth,
            FormatClass::Stencil => stencil,
        }
    }
}

impl Pred {
    /// The struct members the predicate reads.
    pub fn members(&self) -> Vec<&str> {
        match self {
            Pred::AnyBit { member, .. }
            | Pred::NoBit { member, .. }
            | Pred::OneOf { member, .. }
            | Pred::NoneOf { member, .. }
            | Pred::MultipleOf { member, .. }
            | Pred::AbsAtMost { member, .. } => vec![member],
            Pred::Compare {
                member, plus, rhs, ..
            } => {
                let mut out = vec![member.as_str()];
                out.extend(plus.as_deref());
                match rhs {
                    Rhs::Member(other) => out.push(other),
                    Rhs::Extent { level, .. } => out.push(level),
                    _ => {}
                }
                out
            }
            Pred::All(ps) => ps.iter().flat_map(Pred::members).collect(),
            Pred::FormatIs { member, .. } | Pred::AspectsIn { member, .. } => vec![member],
            Pred::Feature { .. }
            | Pred::Usage { .. }
            | Pred::Bound { .. }
            | Pred::ImageType { .. } => Vec::new(),
        }
    }

    /// The handles whose objects' records the predicate reads.
    pub fn handles(&self) -> Vec<&str> {
        match self {
            Pred::Usage { handle, .. }
            | Pred::Bound { handle, .. }
            | Pred::ImageType { handle, .. }
            | Pred::AspectsIn { handle, .. }
            | Pred::Compare {
                rhs: Rhs::Created { handle, .. } | Rhs::Extent { handle, .. },
                ..
            } => vec![handle],
            Pred::All(ps) => ps.iter().flat_map(Pred::handles).collect(),
            _ => Vec::new(),
        }
    }

    /// Whether the predicate reads the device: its features, limits or records.
    fn reads_device(&self) -> bool {
        match self {
            Pred::Feature { .. }
            | Pred::Usage { .. }
            | Pred::Bound { .. }
            | Pred::ImageType { .. }
            | Pred::AspectsIn { .. }
            | Pred::Compare {
                rhs: Rhs::Limit(_) | Rhs::Created { .. } | Rhs::Extent { .. },
                ..
            }
            | Pred::MultipleOf {
                rhs: Rhs::Limit(_), ..
            } => true,
            Pred::All(ps) => ps.iter().any(Pred::reads_device),
            _ => false,
        }
    }

    /// Every path the predicate names, members and handles, for rewriting.
    fn paths_mut(&mut self) -> Vec<&mut String> {
        match self {
            Pred::AnyBit { member, .. }
            | Pred::NoBit { member, .. }
            | Pred::OneOf { member, .. }
            | Pred::NoneOf { member, .. }
            | Pred::MultipleOf { member, .. }
            | Pred::AbsAtMost { member, .. } => vec![member],
            Pred::Compare {
                member, plus, rhs, ..
            } => {
                let mut out = vec![member];
                out.extend(plus.as_mut());
                match rhs {
                    Rhs::Member(m) => out.push(m),
                    Rhs::Created { handle, .. } => out.push(handle),
                    Rhs::Extent { handle, level, .. } => {
                        out.push(handle);
                        out.push(level);
                    }
                    Rhs::Const(_) | Rhs::Limit(_) => {}
                }
                out
            }
            Pred::Usage { handle, .. }
            | Pred::Bound { handle, .. }
            | Pred::ImageType { handle, .. } => vec![handle],
            Pred::FormatIs { member, .. } => vec![member],
            Pred::AspectsIn { member, handle } => vec![member, handle],
            Pred::All(ps) => ps.iter_mut().flat_map(Pred::paths_mut).collect(),
            Pred::Feature { .. } => Vec::new(),
        }
    }
}

impl Check {
    /// Whether the check reads the device: its features or limits.
    pub fn reads_device(&self) -> bool {
        self.when
            .iter()
            .chain(std::iter::once(&self.must))
            .any(Pred::reads_device)
    }

    /// The handles whose objects' records the check reads, each once, in order.
    pub fn handles(&self) -> Vec<&str> {
        self.each_once(Pred::handles)
    }

    /// The struct members the check reads, each once, in order.
    pub fn members(&self) -> Vec<&str> {
        self.each_once(Pred::members)
    }

    /// What `of` names in each predicate, each name once, in order.
    fn each_once<'a>(&'a self, of: impl Fn(&'a Pred) -> Vec<&'a str>) -> Vec<&'a str> {
        let mut out: Vec<&str> = Vec::new();
        for name in self
            .when
            .iter()
            .chain(std::iter::once(&self.must))
            .flat_map(of)
        {
            if !out.contains(&name) {
                out.push(name);
            }
        }
        out
    }
}

/// What a recogniser sees: the rule's text, normalised, and the struct's model.
pub struct Input<'a> {
    text: &'a str,
    item: &'a str,
    model: &'a Model,
    /// The array the rule is about element by element, and its element type.
    each: Option<(String, String)>,
}

type Recogniser = fn(&Input, &str) -> Option<Pred>;

/// The recognisers: what a rule requires, each a phrasing of the specification
/// with its name. A rule is `R` or `If C, C, and C, R` (`then` allowed), where each
/// condition `C` is read by `condition`.
pub const RECOGNISERS: &[(&str, Recogniser)] = &[
    ("flags must (not) include bits", flags_req),
    ("value must (not) be one of", value_req),
    (
        "number compared with a constant, member or limit",
        compare_req,
    ),
    ("object created with usage bits", usage_req),
    ("object bound to memory unless sparse", bound_req),
    (
        "number less than a creation parameter of an object",
        created_req,
    ),
    ("offsets inside an image subresource", inside_req),
    ("aspects present in an image's format", aspects_req),
    ("number between two bounds, inclusive", between_req),
    ("number a multiple of a constant or limit", multiple_req),
    ("feature must be enabled", feature_req),
    ("absolute value at most a limit", abs_req),
    ("flags with no bits but these", other_bits_req),
];

/// Rules whose text, read as written, refuses values that the specification
/// allows elsewhere; a check of them would refuse valid programs, so they are not
/// read. Each with the reason.
pub const NOT_AS_WRITTEN: &[(&str, &str)] = &[
    (
        "VUID-VkRenderPassCreateInfo2-srcSubpass-02526",
        "`VK_SUBPASS_EXTERNAL` is a valid `srcSubpass` (the dependency section says so; later registries add the exception to this rule)",
    ),
    (
        "VUID-VkRenderPassCreateInfo2-dstSubpass-02527",
        "`VK_SUBPASS_EXTERNAL` is a valid `dstSubpass` (the dependency section says so; later registries add the exception to this rule)",
    ),
];

/// Recognise every explicit rule of `rules` whose item is an emitted struct or
/// command.
pub fn recognise(
    model: &Model,
    rules: &[super::Rule],
    reach: &std::collections::BTreeSet<String>,
) -> Vec<Recognised> {
    let mut out = Vec::new();
    for rule in rules {
        if rule.category == super::Category::Implicit
            || !rule.emitted
            || rule.key_holds == Some(false)
            || NOT_AS_WRITTEN.iter().any(|(v, _)| *v == rule.vuid)
            || (model.category(&rule.item) != Some(Kind::Struct)
                && !model.commands.contains_key(&rule.item))
        {
            continue;
        }
        let text = plain(&rule.text);
        let Some((each, body)) = elements(model, &rule.item, &text, reach) else {
            continue;
        };
        let body = normalised(&body);
        let input = Input {
            text: &body,
            item: &rule.item,
            model,
            each,
        };
        if let Some((by, check)) = read_rule(&input) {
            out.push(Recognised {
                vuid: rule.vuid.clone(),
                item: rule.item.clone(),
                by,
                text: text.clone(),
                on_command: model.commands.contains_key(&rule.item),
                check,
                // The check runs where its rule applies: an extension promoted to an
                // emitted version stands for that version too.
                key: rule
                    .key
                    .as_deref()
                    .map(|k| model.with_promotions(k))
                    .filter(|k| {
                        crate::model::expr::Expr::parse(k).is_ok_and(|e| {
                            e.names()
                                .iter()
                                .any(|n| *n != "core" && !n.starts_with("VK_VERSION_"))
                        })
                    }),
            });
        }
    }
    out
}

/// The rule's HTML as one line of text, with code in backticks.
pub fn plain(html: &str) -> String {
    static TAGS: OnceLock<[Regex; 3]> = OnceLock::new();
    let [code, pname, tag] = TAGS.get_or_init(|| {
        [
            Regex::new(r"<code>([^<]*)</code>").expect("pattern"),
            Regex::new(r"pname:([A-Za-z0-9_]+)").expect("pattern"),
            Regex::new(r"<[^>]*>").expect("pattern"),
        ]
    });
    let s = code.replace_all(html, "`$1`");
    let s = pname.replace_all(&s, "`$1`");
    let s = tag.replace_all(&s, "");
    // `VkPhysicalDeviceLimits`::`maxX` is one name, and so is `srcOffsets`[0].x.
    let s = s.replace("`::`", "::");
    static INDEX: OnceLock<Regex> = OnceLock::new();
    let s = re(&INDEX, r"`(\w+)`\[(\d+)\]\.(\w+)").replace_all(&s, "`$1[$2].$3`");
    let s = s
        .replace("&#43;", "+")
        .replace("&lt;", "<")
        .replace("&gt;", ">")
        .replace("&amp;", "&");
    let s = s.split_whitespace().collect::<Vec<_>>().join(" ");
    static SUM: OnceLock<Regex> = OnceLock::new();
    let s = re(&SUM, r"the sum of (`[\w.]+`) and (`[\w.]+`) must").replace_all(&s, "$1 + $2 must");
    s.trim_end_matches('.').to_owned()
}

/// The rule's text with synonyms written one way, so that one pattern reads both:
/// `must equal` is `must be equal to`, and a bare number (`greater than 0`, `must
/// be zero`) is a code span like the others.
fn normalised(text: &str) -> String {
    let s = text
        // The null handle is a link, not a code span, in the rule's HTML.
        .replace(" VK_NULL_HANDLE", " `VK_NULL_HANDLE`")
        .replace(" must not equal ", " must not be equal to ")
        .replace(" must equal ", " must be equal to ")
        .replace(" must also ", " must ");
    // `The sum of a and b must`, `(a + b) must`: `a + b must`.
    static SUM: OnceLock<[Regex; 3]> = OnceLock::new();
    let [sum, paren, minus] = SUM.get_or_init(|| {
        [
            Regex::new(r"\b[Tt]he sum of (`[\w.]+`) and (`[\w.]+`) must").expect("pattern"),
            Regex::new(r"^\((`[\w.]+`) \+ (`[\w.]+`)\) must").expect("pattern"),
            // `b must be <= L minus a` is `a + b <= L`.
            Regex::new(
                r"^(`[\w.]+`) must be less than or equal to (`[\w:.\[\]]+`) minus (`[\w.]+`)$",
            )
            .expect("pattern"),
        ]
    });
    // `maxViewportDimensions`[0]: one name, as `plain` writes an indexed member (before
    // the sums, so that `L`[0] minus `a` reads as a sum under one limit).
    static INDEXED: OnceLock<Regex> = OnceLock::new();
    let s = re(&INDEXED, r"`([\w:]+)`\[(\d+)\]").replace_all(&s, "`$1[$2]`");
    let s = sum.replace_all(&s, "$1 + $2 must");
    let s = paren.replace_all(&s, "$1 + $2 must");
    let s = minus.replace_all(&s, "$3 + $1 must be less than or equal to $2");
    static BARE: OnceLock<Regex> = OnceLock::new();
    let bare = re(
        &BARE,
        r"(must (?:not )?be(?: (?:greater|less) than(?: or equal to)?)?) (\d+(?:\.\d+)?|zero)(,| and |$)",
    );
    bare.replace_all(&s, |c: &regex::Captures| {
        let n = if &c[2] == "zero" { "0" } else { &c[2] };
        format!("{} `{n}`{}", &c[1], &c[3])
    })
    .into_owned()
}

fn re(cell: &'static OnceLock<Regex>, pattern: &str) -> &'static Regex {
    cell.get_or_init(|| Regex::new(pattern).expect("recogniser pattern"))
}

/// A list of code spans: `` `A` ``, `` `A` or `B` ``, `` `A`, `B`, or `C` `` (the
/// specification sometimes drops a comma).
const LIST: &str = r"`[A-Z0-9_.]+`(?:,? (?:or )?`[A-Z0-9_.]+`)*";

/// The names in a list matched by [`LIST`].
fn names(list: &str) -> Vec<&str> {
    list.split('`')
        .skip(1)
        .step_by(2)
        .filter(|s| !s.is_empty())
        .collect()
}

/// Split `If C, C, and C, R` into conditions and requirement, and read both; then
/// name the members of the array's element as `array[].member`.
fn read_rule(input: &Input) -> Option<(&'static str, Check)> {
    let (by, when, must) = read_parts(input)?;
    let mut check = Check {
        when,
        must,
        each: None,
    };
    if let Some((array, element)) = &input.each {
        let mut in_element = false;
        for p in check
            .when
            .iter_mut()
            .chain(std::iter::once(&mut check.must))
        {
            for path in p.paths_mut() {
                if field_in(input.model, element, path).is_some() {
                    *path = format!("{array}[].{path}");
                    in_element = true;
                }
            }
        }
        // A rule "for each element" that reads nothing of the element is read as
        // written of the whole; one that does is checked per element.
        in_element.then_some(())?;
        let count = match input.model.commands.get(input.item) {
            Some(_) => None,
            None => {
                let t = input.model.types.get(input.item)?;
                let m = t.members.iter().find(|m| &m.name == array)?;
                Some(m.len.as_deref()?.split(',').next()?.to_owned())
            }
        };
        check.each = Some(Each {
            array: array.clone(),
            count,
        });
    }
    Some((by, check))
}

fn read_parts(input: &Input) -> Option<(&'static str, Vec<Pred>, Pred)> {
    // A requirement that is itself phrased with `If` (`If buffer is non-sparse then
    // it must be bound ...`) is one requirement, with no conditions.
    if let Some((by, must)) = requirement(input, input.text) {
        return Some((by, Vec::new(), must));
    }
    let (conds, req) = match input.text.strip_prefix("If ") {
        None => (Vec::new(), input.text),
        Some(rest) => split_conditions(rest)?,
    };
    let when = conds
        .iter()
        .map(|c| condition(input, c))
        .collect::<Option<Vec<_>>>()?;
    // `If x is not C, it must ...`: `it` is the subject of the last condition.
    let req = match (req.strip_prefix("it must "), conds.last()) {
        (Some(rest), Some(last)) if last.starts_with('`') => {
            let subject = last.split('`').nth(1)?;
            format!("`{subject}` must {rest}")
        }
        _ => req.to_owned(),
    };
    // `If m includes A, then bits other than B must not be set`: of `m`.
    let req = match (req.strip_prefix("bits other than "), conds.last()) {
        (Some(rest), Some(last)) if last.starts_with('`') && rest.ends_with(" must not be set") => {
            let subject = last.split('`').nth(1)?;
            let list = rest.trim_end_matches(" must not be set");
            format!("`{subject}` must not include bits other than {list}")
        }
        _ => req,
    };
    let (by, mut must) = requirement(input, &req)?;
    // A requirement never forbids the bits its own condition asks for (`if usage
    // has TRANSIENT, no bits but COLOR ...`: TRANSIENT itself stays allowed).
    if let Pred::NoBit { member, bits } = &mut must {
        for p in &when {
            if let Pred::AnyBit {
                member: m,
                bits: asked,
            } = p
            {
                if m == member {
                    bits.retain(|b| !asked.iter().any(|a| a.number == b.number));
                }
            }
        }
        (!bits.is_empty()).then_some(())?;
    }
    Some((by, when, must))
}

/// A requirement, as the first recogniser that reads it sees it; or one that names
/// several subjects (`` `a`, `b` and `c` must not be `X` ``, `` `a` and `b` must
/// each be either `X` or `Y` ``, `` ... must be multiples of `4` ``), read as the
/// same requirement of each subject, all of which must hold.
fn requirement(input: &Input, req: &str) -> Option<(&'static str, Pred)> {
    if let Some(found) = RECOGNISERS
        .iter()
        .find_map(|(name, f)| f(input, req).map(|p| (*name, p)))
    {
        return Some(found);
    }
    static R: OnceLock<Regex> = OnceLock::new();
    let r = re(
        &R,
        r"^((?:`[\w.]+`, )*`[\w.]+`,? and `[\w.]+`) must (?:each |both )?(.+)$",
    );
    let c = whole(r, req)?;
    let rest =
        c[1].replacen("be either ", "be ", 1)
            .replacen("be multiples of ", "be a multiple of ", 1);
    let mut by = None;
    let mut all = Vec::new();
    for subject in names(&c[0]) {
        let (name, p) = RECOGNISERS.iter().find_map(|(name, f)| {
            f(input, &format!("`{subject}` must {rest}")).map(|p| (*name, p))
        })?;
        (by.is_none() || by == Some(name)).then_some(())?;
        by = Some(name);
        all.push(p);
    }
    Some((by?, Pred::All(all)))
}

/// A rule about each element of an array, rewritten as a rule about one element:
/// `For each element of A, R`, `If C, then for each element of A, R`, `The x
/// member of each element of A must ...`, `The x + y of each element of A must
/// ...`. Returns the array and its element type (if any) and the rule's text;
/// `None` when the array is not an array of structs of the item, or the rule
/// excludes elements by a chained struct that a program enabling only `reach` can
/// chain.
fn elements(
    model: &Model,
    item: &str,
    text: &str,
    reach: &std::collections::BTreeSet<String>,
) -> Option<(Option<(String, String)>, String)> {
    static R: OnceLock<[Regex; 5]> = OnceLock::new();
    let [each, each_not, then_each, member_of, its] = R.get_or_init(|| {
        [
            Regex::new(r"^For each (?:\w+ )?element of `(\w+)`, (.*)$"),
            Regex::new(
                r"^For each element of `(\w+)` not containing `(\w+)` in its `pNext` chain, (.*)$",
            ),
            Regex::new(r"^If (.*), then for each element of `(\w+)`, (.*)$"),
            Regex::new(
                r"^The (`[\w.\[\]]+`(?: \+ `[\w.\[\]]+`)?)(?: member)? of each element of `(\w+)` (must .*)$",
            ),
            Regex::new(
                r"^If the `(\w+)` member of an element of `(\w+)` (is [^,]*), its `(\w+)` member (must .*)$",
            ),
        ]
        .map(|r| r.expect("element pattern"))
    });
    let (array, body) = if let Some(c) = each_not.captures(text) {
        // Elements that chain a struct no such program can chain are none of them.
        let condition = model.condition(&c[2]);
        let chainable = condition.is_core() || condition.expr().eval(reach);
        (!chainable && model.types.contains_key(&c[2])).then_some(())?;
        (c[1].to_owned(), capitalised(&c[3]))
    } else if let Some(c) = each.captures(text) {
        (c[1].to_owned(), capitalised(&c[2]))
    } else if let Some(c) = then_each.captures(text) {
        (c[2].to_owned(), format!("If {}, {}", &c[1], &c[3]))
    } else if let Some(c) = member_of.captures(text) {
        (c[2].to_owned(), format!("{} {}", &c[1], &c[3]))
    } else if let Some(c) = its.captures(text) {
        (
            c[2].to_owned(),
            format!("If `{}` {}, `{}` {}", &c[1], &c[3], &c[4], &c[5]),
        )
    } else {
        return Some((None, text.to_owned()));
    };
    let fields = match model.commands.get(item) {
        Some(cmd) => &cmd.params,
        None => &model.types.get(item)?.members,
    };
    let f = fields.iter().find(|f| f.name == array)?;
    (f.pointers == 1 && f.len.is_some() && model.category(&f.type_name) == Some(Kind::Struct))
        .then_some(())?;
    Some((Some((array, f.type_name.clone())), body))
}

/// `if x` as `If x`.
fn capitalised(text: &str) -> String {
    match text.strip_prefix("if ") {
        Some(rest) => format!("If {rest}"),
        None => text.to_owned(),
    }
}

/// The conditions of `C, C, and C, R` and the requirement `R`: the requirement is
/// the last comma-separated part that holds `must`.
fn split_conditions(rest: &str) -> Option<(Vec<&str>, &str)> {
    let at = rest.find(" must ")?;
    // `If C then R`, with no comma, splits at `then`.
    // `, then` ends the conditions even when the requirement holds a list with
    // commas.
    let (cut, skip) = match (rest[..at].rfind(", then "), rest[..at].rfind(", ")) {
        (Some(cut), _) | (None, Some(cut)) => (cut, 2),
        (None, None) => (rest[..at].rfind(" then ")?, 1),
    };
    let req = rest[cut + skip..].trim_start_matches("then ");
    let mut conds = Vec::new();
    for part in rest[..cut].split(", ") {
        let part = part.trim_start_matches("and ");
        for c in part.split(" and ") {
            conds.push(c);
        }
    }
    Some((conds, req))
}

/// A member path: a member of the struct, or of a struct member by value
/// (`extent.width`), without pointers; an element of a fixed-size array is
/// `offsets[1].x`. For a rule about each element of an array, a path is first
/// looked up in the element.
fn member<'a>(input: &Input<'a>, path: &str) -> Option<&'a crate::model::Field> {
    if let Some((_, element)) = &input.each {
        if let Some(f) = field_in(input.model, element, path) {
            return Some(f);
        }
    }
    path_field(input.model, input.item, path)
}

/// One part of a path: a name, with `[N]` for an element of a fixed-size array or
/// `[]` for the element a rule is about.
fn part(s: &str) -> (&str, Option<&str>) {
    match s.split_once('[') {
        Some((name, rest)) => (name, Some(rest.trim_end_matches(']'))),
        None => (s, None),
    }
}

/// Whether a field fits a path part: plain, an indexed fixed-size array, or (`[]`)
/// a counted array of structs.
fn fits(m: &crate::model::Field, index: Option<&str>) -> bool {
    if m.bitfield.is_some() {
        return false;
    }
    match index {
        None => m.pointers == 0 && m.static_array.is_none(),
        Some("") => m.pointers == 1 && m.len.is_some(),
        Some(i) => {
            m.pointers == 0 && m.static_array.is_some() && i.chars().all(|c| c.is_ascii_digit())
        }
    }
}

/// The field a path names in a struct type.
fn field_in<'a>(model: &'a Model, ty: &str, path: &str) -> Option<&'a crate::model::Field> {
    let mut ty = ty;
    let mut found = None;
    for p in path.split('.') {
        let (name, index) = part(p);
        let t = model.types.get(ty)?;
        let m = t
            .members
            .iter()
            .find(|m| m.name == name && fits(m, index))?;
        ty = &m.type_name;
        found = Some(m);
    }
    found
}

/// The field (parameter or member) a path names from an item: a command's
/// parameters, or a struct's members, then members of those.
pub fn path_field<'a>(model: &'a Model, item: &str, path: &str) -> Option<&'a crate::model::Field> {
    match model.commands.get(item) {
        Some(cmd) => {
            let (first, rest) = match path.split_once('.') {
                Some((f, r)) => (f, Some(r)),
                None => (path, None),
            };
            let (name, index) = part(first);
            let p = cmd
                .params
                .iter()
                .find(|p| p.name == name && fits(p, index))?;
            match rest {
                None => Some(p),
                Some(rest) => field_in(model, &p.type_name, rest),
            }
        }
        None => field_in(model, item, path),
    }
}

/// The first part of a path, without an index: the parameter or member it starts
/// from.
pub fn root(path: &str) -> &str {
    let first = path.split('.').next().unwrap_or_default();
    part(first).0
}

/// A condition: `` the `f` feature is (not) enabled ``, `` `flags` includes `A` ``,
/// `` `flags` does not include `A` ``, `` `value` is (not) (equal to) `A` ``.
fn condition(input: &Input, text: &str) -> Option<Pred> {
    // `the x member is ...` is `x is ...`; `does not have the value C` is `is not C`.
    static MEMBER: OnceLock<Regex> = OnceLock::new();
    let text = re(&MEMBER, r"^the (`[\w.]+`) member ").replace(text, "$1 ");
    let text = text.replace(" does not have the value ", " is not ");
    let text = text.as_str();
    static SET: OnceLock<Regex> = OnceLock::new();
    let set_in = re(
        &SET,
        &format!(r"^({LIST}) (?:is|are) (not )?set in `([\w.]+)`$"),
    );
    if let Some(c) = whole(set_in, text) {
        let bits = flag_list(input, &c[2], &c[0])?;
        let member = c[2].clone();
        return Some(if c[1].is_empty() {
            Pred::AnyBit { member, bits }
        } else {
            Pred::NoBit { member, bits }
        });
    }
    static R: OnceLock<[Regex; 5]> = OnceLock::new();
    let [feat, incl, excl, is, of_type] = R.get_or_init(|| {
        [
            Regex::new(r"^the `(\w+)` feature is (not )?enabled$"),
            Regex::new(&format!(r"^`([\w.]+)` (?:includes|contains) ({LIST})$")),
            Regex::new(&format!(
                r"^`([\w.]+)` does not (?:include|contain) ({LIST})$"
            )),
            Regex::new(&format!(r"^`([\w.]+)` is (not )?(?:equal to )?({LIST})$")),
            Regex::new(&format!(r"^`([\w.]+)` is of type ({LIST})$")),
        ]
        .map(|r| r.expect("condition pattern"))
    });
    if let Some(p) = format_condition(input, text) {
        return Some(p);
    }
    if let Some(c) = whole(of_type, text) {
        (object(input, &c[0])? == Object::Image).then_some(())?;
        return Some(Pred::ImageType {
            handle: c[0].clone(),
            values: resolve(input, "VkImageType", &names(&c[1]))?,
        });
    }
    if let Some(c) = whole(feat, text) {
        let (name, core) = feature(input, &c[0])?;
        return Some(Pred::Feature {
            name,
            core,
            enabled: c[1].is_empty(),
        });
    }
    if let Some(c) = whole(incl, text) {
        let bits = flag_list(input, &c[0], &c[1])?;
        return Some(Pred::AnyBit {
            member: c[0].clone(),
            bits,
        });
    }
    if let Some(c) = whole(excl, text) {
        let bits = flag_list(input, &c[0], &c[1])?;
        return Some(Pred::NoBit {
            member: c[0].clone(),
            bits,
        });
    }
    let c = whole(is, text)?;
    value_pred(input, &c[0], c[1].is_empty(), &c[2])
}

/// `` `format` is a color format ``, `` ... is a depth/stencil format (which
/// includes only the depth aspect, ... both depth and stencil aspects) ``,
/// `` `format` includes a color or depth aspect ``, `` ... includes a stencil
/// aspect ``: a `VkFormat` member of a kind.
fn format_condition(input: &Input, text: &str) -> Option<Pred> {
    static R: OnceLock<Regex> = OnceLock::new();
    let r = re(
        &R,
        r"^`([\w.\[\]]+)` (is a color format|is a depth/stencil format|is a depth/stencil format which includes only the depth aspect|is a depth/stencil format which includes only the stencil aspect|is a depth/stencil format which includes both depth and stencil aspects|includes a color or depth aspect|includes a stencil aspect)$",
    );
    let c = whole(r, text)?;
    (member(input, &c[0])?.type_name == "VkFormat").then_some(())?;
    let class = match c[1].as_str() {
        "is a color format" => FormatClass::Color,
        "is a depth/stencil format" => FormatClass::DepthStencil,
        "includes a color or depth aspect" => FormatClass::ColorOrDepth,
        "includes a stencil aspect" => FormatClass::Stencil,
        t if t.ends_with("only the depth aspect") => FormatClass::DepthOnly,
        t if t.ends_with("only the stencil aspect") => FormatClass::StencilOnly,
        _ => FormatClass::DepthAndStencil,
    };
    Some(Pred::FormatIs {
        member: c[0].clone(),
        class,
    })
}

/// `` `aspectMask` must specify aspects present in `image` ``.
fn aspects_req(input: &Input, text: &str) -> Option<Pred> {
    static R: OnceLock<Regex> = OnceLock::new();
    let r = re(
        &R,
        r"^`([\w.\[\]]+)` must specify aspects present in `(\w+)`$",
    );
    let c = whole(r, text)?;
    (member(input, &c[0])?.type_name == "VkImageAspectFlags").then_some(())?;
    (object(input, &c[1])? == Object::Image).then_some(())?;
    Some(Pred::AspectsIn {
        member: c[0].clone(),
        handle: c[1].clone(),
    })
}

/// An enum or `VkBool32` member is (not) one of a list, or a number member is (not)
/// a constant.
fn value_pred(input: &Input, path: &str, positive: bool, list: &str) -> Option<Pred> {
    let listed = names(list);
    let m = member(input, path)?;
    let member_name = path.to_owned();
    let is_number = |n: &&str| n.chars().all(|c| c.is_ascii_digit() || c == '.');
    if let [Some(value)] = listed
        .iter()
        .map(|n| constant(n, &m.type_name))
        .collect::<Vec<_>>()
        .as_slice()
    {
        return Some(Pred::Compare {
            member: member_name,
            plus: None,
            op: if positive { Op::Eq } else { Op::Ne },
            rhs: Rhs::Const((*value).to_owned()),
            float: false,
            unsigned: true,
        });
    }
    if numeric(&m.type_name) && listed.iter().all(is_number) {
        if let [n] = listed.as_slice() {
            return Some(Pred::Compare {
                member: member_name,
                plus: None,
                op: if positive { Op::Eq } else { Op::Ne },
                rhs: Rhs::Const((*n).to_owned()),
                float: m.type_name == "float",
                unsigned: unsigned(&m.type_name),
            });
        }
        // `drawCount must be 0 or 1`: whole numbers only.
        let values = listed
            .iter()
            .map(|n| {
                Some(Value {
                    name: (*n).to_owned(),
                    number: n.parse().ok()?,
                })
            })
            .collect::<Option<Vec<_>>>()?;
        return Some(if positive {
            Pred::OneOf {
                member: member_name,
                values,
            }
        } else {
            Pred::NoneOf {
                member: member_name,
                values,
            }
        });
    }
    let values = if m.type_name == "VkBool32" {
        listed
            .iter()
            .map(|n| {
                let number = match *n {
                    "VK_FALSE" => 0,
                    "VK_TRUE" => 1,
                    _ => return None,
                };
                Some(Value {
                    name: (*n).to_owned(),
                    number,
                })
            })
            .collect::<Option<Vec<_>>>()?
    } else {
        let (group, kind) = values_group(input, path)?;
        (kind == Kind::Enum).then_some(())?;
        resolve(input, group, &listed)?
    };
    Some(if positive {
        Pred::OneOf {
            member: member_name,
            values,
        }
    } else {
        Pred::NoneOf {
            member: member_name,
            values,
        }
    })
}

/// An API constant a number member is compared with, as a Rust expression of the
/// member's type: the specification defines each as all bits set (`(~0U)`,
/// `(~0ULL)`), but `VK_NULL_HANDLE`, which is 0.
fn constant(name: &str, c_type: &str) -> Option<&'static str> {
    match (name, c_type) {
        (
            "VK_ATTACHMENT_UNUSED"
            | "VK_SUBPASS_EXTERNAL"
            | "VK_REMAINING_MIP_LEVELS"
            | "VK_REMAINING_ARRAY_LAYERS"
            | "VK_QUEUE_FAMILY_IGNORED",
            "uint32_t",
        ) => Some("u32::MAX"),
        ("VK_WHOLE_SIZE", "VkDeviceSize" | "uint64_t") => Some("u64::MAX"),
        // A handle carried as a number (`objectHandle`): the null handle is 0.
        ("VK_NULL_HANDLE", "uint64_t") => Some("0"),
        _ => None,
    }
}

/// The values group (enum type, or the bits type of a flags type) of a member.
fn values_group<'a>(input: &Input<'a>, path: &str) -> Option<(&'a str, Kind)> {
    let m = member(input, path)?;
    let t = input.model.types.get(&m.type_name)?;
    match t.category? {
        Kind::Enum => Some((&t.name, Kind::Enum)),
        Kind::Bitmask => Some((t.bit_values.as_deref()?, Kind::Bitmask)),
        _ => None,
    }
}

/// Resolve names of values of `group`; `None` unless every one resolves.
fn resolve(input: &Input, group: &str, names: &[&str]) -> Option<Vec<Value>> {
    let known = input.model.enum_values.get(group)?;
    names
        .iter()
        .map(|n| {
            known.iter().any(|k| k == n).then_some(())?;
            Some(Value {
                name: (*n).to_owned(),
                number: *input.model.enum_numbers.get(*n)?,
            })
        })
        .collect()
}

/// The bits of a flags member that a list names.
fn flag_list(input: &Input, path: &str, list: &str) -> Option<Vec<Value>> {
    let (group, kind) = values_group(input, path)?;
    (kind == Kind::Bitmask).then_some(())?;
    resolve(input, group, &names(list))
}

/// The bits of `group` whose names match a `*` pattern, vendor suffixes and the
/// plural of the last word allowed.
fn glob(input: &Input, group: &str, pattern: &str) -> Option<Vec<Value>> {
    // A plural name is the stage that stands for a set of them:
    // `VK_PIPELINE_STAGE_2_PRE_RASTERIZATION_SHADERS_BIT` is every pre-rasterization
    // `*_SHADER_BIT` stage, so a mask that includes it includes one of those.
    let body = regex::escape(pattern)
        .replace(r"\*", "[A-Z0-9_]*")
        .replace("_BIT", "S?_BIT");
    let re = Regex::new(&format!("^{body}(?:_[A-Z]+)?$")).ok()?;
    let known = input.model.enum_values.get(group)?;
    let found: Vec<&str> = known
        .iter()
        .filter(|k| re.is_match(k))
        .map(String::as_str)
        .collect();
    (!found.is_empty()).then_some(())?;
    resolve(input, group, &found)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn plain_text_keeps_code_and_drops_markup() {
        let html = r##" If the <a href="#features-geometryShader"><code>geometryShader</code></a> feature is not enabled, pname:srcStageMask <strong class="purple">must</strong> not contain <code>VK_PIPELINE_STAGE_2_GEOMETRY_SHADER_BIT</code>."##;
        assert_eq!(
            plain(html),
            "If the `geometryShader` feature is not enabled, `srcStageMask` must not contain `VK_PIPELINE_STAGE_2_GEOMETRY_SHADER_BIT`"
        );
    }

    #[test]
    fn lists_with_and_without_commas() {
        assert_eq!(names("`A`, `B`, or `C`"), ["A", "B", "C"]);
        assert_eq!(names("`A` `B`, or `C`"), ["A", "B", "C"]);
        let r = Regex::new(&format!("^{LIST}$")).expect("pattern");
        assert!(r.is_match("`A` or `B`"));
        assert!(r.is_match("`A_BIT` `B_BIT`, or `C_BIT`"));
        assert!(!r.is_match("`A` and `B`"));
    }
}
