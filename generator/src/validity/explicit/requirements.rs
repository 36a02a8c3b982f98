//! The requirement readers of the recogniser pass: each reads one phrasing of what
//! a rule requires (flags, values, comparisons, bounds, multiples, features, usage,
//! creation parameters, ranges inside another object) into a [`Pred`].

use super::*;

/// The core features structs, and the field of the generated crate's `Features`
/// (what a device was created with) that holds each.
pub const CORE_FEATURES: &[(&str, &str)] = &[
    ("VkPhysicalDeviceFeatures", "v10"),
    ("VkPhysicalDeviceVulkan11Features", "v11"),
    ("VkPhysicalDeviceVulkan12Features", "v12"),
    ("VkPhysicalDeviceVulkan13Features", "v13"),
];

/// The field of `Features` that holds a core feature, if `name` is one.
pub fn core_feature(model: &Model, name: &str) -> Option<&'static str> {
    CORE_FEATURES.iter().find_map(|(ty, field)| {
        model
            .types
            .get(*ty)?
            .members
            .iter()
            .any(|m| m.name == name && m.type_name == "VkBool32")
            .then_some(*field)
    })
}

/// A core feature by name, with where the device keeps it.
pub(super) fn feature(input: &Input, name: &str) -> Option<(String, &'static str)> {
    Some((name.to_owned(), core_feature(input.model, name)?))
}

pub(super) fn whole(re: &Regex, text: &str) -> Option<Vec<String>> {
    let c = re.captures(text)?;
    Some(
        c.iter()
            .skip(1)
            .map(|m| m.map_or(String::new(), |m| m.as_str().to_owned()))
            .collect(),
    )
}

/// `` `flags` must (not) contain/include `A`, `B`, or one of the
/// `VK_PIPELINE_STAGE_*_SHADER_BIT` stages ``.
pub(super) fn flags_req(input: &Input, text: &str) -> Option<Pred> {
    static R: OnceLock<Regex> = OnceLock::new();
    let r = re(
        &R,
        &format!(
            r"^`([\w.]+)` must (not )?(?:contain|include) ({LIST})(?:,? or one of (?:the )?`([A-Z0-9_*]+)` stages)?$"
        ),
    );
    let c = whole(r, text)?;
    let mut bits = flag_list(input, &c[0], &c[2])?;
    if !c[3].is_empty() {
        let (group, _) = values_group(input, &c[0])?;
        bits.extend(glob(input, group, &c[3])?);
    }
    let member = c[0].clone();
    Some(if c[1].is_empty() {
        Pred::AnyBit { member, bits }
    } else {
        Pred::NoBit { member, bits }
    })
}

/// `` `value` must (not) be (equal to) `A` or `B` ``, `` `count` must be `1` ``,
/// `` `x` must not be `0` ``.
pub(super) fn value_req(input: &Input, text: &str) -> Option<Pred> {
    static R: OnceLock<Regex> = OnceLock::new();
    let r = re(
        &R,
        &format!(r"^`([\w.]+)` must (not )?be (?:equal to )?({LIST}),?$"),
    );
    let c = whole(r, text)?;
    value_pred(input, &c[0], c[1].is_empty(), &c[2])
}

/// `` `x` must be greater than (or equal to) `0` ``, `` less than or equal to
/// `VkPhysicalDeviceLimits::maxY` ``, `` less than or equal to `y` ``.
pub(super) fn compare_req(input: &Input, text: &str) -> Option<Pred> {
    static R: OnceLock<Regex> = OnceLock::new();
    let r = re(
        &R,
        r"^`([\w.\[\]]+)`(?: \+ `([\w.\[\]]+)`)? must be (greater than|less than|equal to) (or equal to )?`([\w:.\[\]]+)`$",
    );
    let mut c = whole(r, text)?;
    let m = member(input, &c[0])?;
    numeric(&m.type_name).then_some(())?;
    let plus = summand(input, &c.remove(1), m.type_name == "float")?;
    let op = match (c[1].as_str(), c[2].is_empty()) {
        ("greater than", true) => Op::Gt,
        ("greater than", false) => Op::Ge,
        ("less than", true) => Op::Lt,
        ("less than", false) => Op::Le,
        ("equal to", true) => Op::Eq,
        _ => return None,
    };
    let rhs = &c[3];
    let limits = input.model.types.get("VkPhysicalDeviceLimits")?;
    let mut float = m.type_name == "float";
    // A limit, or an element of an array limit (`viewportBoundsRange[1]`).
    let mut limit = |name: &str| {
        let (base, index) = part(name);
        let l = limits.members.iter().find(|l| {
            l.name == base
                && numeric(&l.type_name)
                && match (index, l.static_array.as_deref()) {
                    (None, None) => true,
                    (Some(i), Some(n)) => i.parse::<usize>().ok() < n.parse::<usize>().ok(),
                    _ => false,
                }
        })?;
        float |= l.type_name == "float";
        Some(Rhs::Limit(name.to_owned()))
    };
    let rhs = if rhs.chars().all(|ch| ch.is_ascii_digit() || ch == '.') {
        Rhs::Const(rhs.clone())
    } else if let Some(name) = rhs.strip_prefix("VkPhysicalDeviceLimits::") {
        limit(name)?
    } else if let Some(other) = member(input, rhs) {
        numeric(&other.type_name).then_some(())?;
        float |= other.type_name == "float";
        Rhs::Member(rhs.clone())
    } else {
        // A bare limit name (`maxFramebufferWidth`) where the struct has no such
        // member.
        limit(rhs)?
    };
    Some(Pred::Compare {
        member: c[0].clone(),
        plus,
        op,
        rhs,
        float,
        unsigned: unsigned(&m.type_name),
    })
}

/// The second member of a sum, if the text has one: `Some(None)` when it has
/// none, `None` when it names no member of the first's kind (whole numbers, or
/// floating-point ones when `float`).
pub(super) fn summand(input: &Input, path: &str, float: bool) -> Option<Option<String>> {
    if path.is_empty() {
        return Some(None);
    }
    let m = member(input, path)?;
    (numeric(&m.type_name) && (m.type_name == "float") == float).then(|| Some(path.to_owned()))
}

/// `` `x` must be between `0.0` and `1.0`, inclusive ``, `` ... between `1.0` and
/// `VkPhysicalDeviceLimits::maxY`, inclusive ``: both comparisons.
pub(super) fn between_req(input: &Input, text: &str) -> Option<Pred> {
    static R: OnceLock<Regex> = OnceLock::new();
    let r = re(
        &R,
        r"^`([\w.\[\]]+)` must be between `([\w:.]+)` and `([\w:.]+)`,? inclusive$",
    );
    let c = whole(r, text)?;
    let low = compare_req(
        input,
        &format!("`{}` must be greater than or equal to `{}`", c[0], c[1]),
    )?;
    let high = compare_req(
        input,
        &format!("`{}` must be less than or equal to `{}`", c[0], c[2]),
    )?;
    Some(Pred::All(vec![low, high]))
}

/// `` `offset` must be a multiple of `4` ``, `` ... an integer multiple of
/// `VkPhysicalDeviceLimits::minY` ``.
pub(super) fn multiple_req(input: &Input, text: &str) -> Option<Pred> {
    static R: OnceLock<Regex> = OnceLock::new();
    let r = re(
        &R,
        r"^`([\w.\[\]]+)` must be (?:an integer |a )?multiple of `([\w:.]+)`$",
    );
    let c = whole(r, text)?;
    let m = member(input, &c[0])?;
    (numeric(&m.type_name) && m.type_name != "float").then_some(())?;
    let rhs = if c[1].chars().all(|ch| ch.is_ascii_digit()) {
        (c[1] != "0").then_some(())?;
        Rhs::Const(c[1].clone())
    } else {
        let name = c[1]
            .strip_prefix("VkPhysicalDeviceLimits::")
            .unwrap_or(&c[1]);
        let limits = input.model.types.get("VkPhysicalDeviceLimits")?;
        limits.members.iter().find(|l| {
            l.name == name
                && l.static_array.is_none()
                && numeric(&l.type_name)
                && l.type_name != "float"
        })?;
        Rhs::Limit(name.to_owned())
    };
    Some(Pred::MultipleOf {
        member: c[0].clone(),
        rhs,
    })
}

/// `` The absolute value of `height` must be less than or equal to
/// `VkPhysicalDeviceLimits::maxY` ``.
pub(super) fn abs_req(input: &Input, text: &str) -> Option<Pred> {
    static R: OnceLock<Regex> = OnceLock::new();
    let r = re(
        &R,
        r"^The absolute value of `([\w.]+)` must be less than or equal to `([\w:\[\]]+)`$",
    );
    let c = whole(r, text)?;
    // The limit as the comparison recogniser reads it.
    let Pred::Compare { rhs, .. } = compare_req(
        input,
        &format!("`{}` must be less than or equal to `{}`", c[0], c[1]),
    )?
    else {
        return None;
    };
    matches!(rhs, Rhs::Limit(_)).then_some(())?;
    Some(Pred::AbsAtMost {
        member: c[0].clone(),
        rhs,
    })
}

/// `` `usage` must not include bits other than `A`, `B`, and `C` ``: none of the
/// type's other bits. (A condition's bits on the same member stay allowed: see
/// [`read_parts`].)
pub(super) fn other_bits_req(input: &Input, text: &str) -> Option<Pred> {
    static R: OnceLock<Regex> = OnceLock::new();
    let r = re(
        &R,
        r"^`([\w.]+)` must not include bits other than (`[A-Z0-9_]+`(?:,? (?:or |and )?`[A-Z0-9_]+`)*)$",
    );
    let c = whole(r, text)?;
    let allowed = flag_list(input, &c[0], &c[1])?;
    let (group, _) = values_group(input, &c[0])?;
    let all = input.model.enum_values.get(group)?;
    let bits: Vec<Value> = all
        .iter()
        .filter_map(|n| {
            Some(Value {
                name: n.clone(),
                number: *input.model.enum_numbers.get(n)?,
            })
        })
        .filter(|v| (v.number as u64).is_power_of_two())
        .filter(|v| !allowed.iter().any(|a| a.number == v.number))
        .collect();
    (!bits.is_empty()).then_some(())?;
    Some(Pred::NoBit {
        member: c[0].clone(),
        bits,
    })
}

/// `` The `synchronization2` feature must be enabled `` (alone or after
/// conditions).
pub(super) fn feature_req(input: &Input, text: &str) -> Option<Pred> {
    static R: OnceLock<Regex> = OnceLock::new();
    let r = re(&R, r"^[Tt]he `(\w+)` feature must be enabled$");
    let c = whole(r, text)?;
    let (name, core) = feature(input, &c[0])?;
    Some(Pred::Feature {
        name,
        core,
        enabled: true,
    })
}

/// A number as the text writes it, written as a Rust literal of the compared type
/// (`0` of a `float` is `0.0`).
pub fn number(text: &str, float: bool) -> String {
    if float && !text.contains('.') {
        format!("{text}.0")
    } else {
        text.to_owned()
    }
}

/// Whether a value list names `VkBool32` constants or numbers rather than enum
/// values, so the member is compared as it is rather than through `as_raw()`.
pub fn is_bool(values: &[Value]) -> bool {
    values.iter().all(|v| {
        v.name == "VK_TRUE"
            || v.name == "VK_FALSE"
            || v.name.starts_with(|c: char| c.is_ascii_digit())
    })
}

/// A handle member or parameter that names a buffer or an image.
pub(super) fn object(input: &Input, path: &str) -> Option<Object> {
    Object::of(&member(input, path)?.type_name)
}

/// `` `buffer` must have been created with `E` usage flag ``, `` ... with the `E`
/// bit set ``, `` ... with the `E` usage bit set ``.
pub(super) fn usage_req(input: &Input, text: &str) -> Option<Pred> {
    static R: OnceLock<Regex> = OnceLock::new();
    let r = re(
        &R,
        &format!(
            r"^`([\w.]+)` must have been created with (?:the )?({LIST}) (?:usage flag|usage bit set|bit set)$"
        ),
    );
    let c = whole(r, text)?;
    let object = object(input, &c[0])?;
    let bits = resolve(input, object.usage_bits(), &names(&c[1]))?;
    Some(Pred::Usage {
        handle: c[0].clone(),
        object,
        bits,
    })
}

/// `` If `buffer` is non-sparse then it must be bound completely and contiguously to
/// a single `VkDeviceMemory` object ``.
pub(super) fn bound_req(input: &Input, text: &str) -> Option<Pred> {
    static R: OnceLock<Regex> = OnceLock::new();
    let r = re(
        &R,
        r"^If `([\w.]+)` is non-sparse then it must be bound completely and contiguously to a single `VkDeviceMemory` object$",
    );
    let c = whole(r, text)?;
    Some(Pred::Bound {
        object: object(input, &c[0])?,
        handle: c[0].clone(),
    })
}

/// `` `offset` must be less than the size of `buffer` ``, `` `mipLevel` must be less
/// than the `mipLevels` specified in VkImageCreateInfo when `image` was created ``,
/// `` `baseArrayLayer` + `layerCount` must be less than or equal to the
/// `arrayLayers` ... ``.
pub(super) fn created_req(input: &Input, text: &str) -> Option<Pred> {
    static R: OnceLock<[Regex; 2]> = OnceLock::new();
    let [size, image] = R.get_or_init(|| {
        [
            Regex::new(
                r"^`([\w.\[\]]+)`(?: \+ `([\w.\[\]]+)`)? must be less than (or equal to (?:than )?)?the size of `([\w.]+)`(?: minus `([\w.\[\]]+)`)?$",
            ),
            Regex::new(
                r"^`([\w.\[\]]+)`(?: \+ `([\w.\[\]]+)`)? must be less than (or equal to )?the `(mipLevels|arrayLayers)` specified in VkImageCreateInfo when `([\w.]+)` was created$",
            ),
        ]
        .map(|r| r.expect("recogniser pattern"))
    });
    let (m, plus, op, handle, object, field) = if let Some(c) = whole(size, text) {
        // `size must be <= the size of b minus offset` is `offset + size <= size of
        // b`: an offset and a size or count are written in that order.
        let (m, plus) = match (c[1].is_empty(), c[4].is_empty()) {
            (_, true) => (c[0].clone(), c[1].clone()),
            (true, false) => (c[4].clone(), c[0].clone()),
            (false, false) => return None,
        };
        let op = if c[2].is_empty() { Op::Lt } else { Op::Le };
        (m, plus, op, c[3].clone(), Object::Buffer, "size".to_owned())
    } else {
        let c = whole(image, text)?;
        let op = if c[2].is_empty() { Op::Lt } else { Op::Le };
        (
            c[0].clone(),
            c[1].clone(),
            op,
            c[4].clone(),
            Object::Image,
            c[3].clone(),
        )
    };
    (self::object(input, &handle)? == object).then_some(())?;
    let plus = summand(input, &plus, false)?;
    let t = &member(input, &m)?.type_name;
    numeric(t).then_some(())?;
    Some(Pred::Compare {
        member: m,
        plus,
        op,
        rhs: Rhs::Created {
            handle,
            object,
            field,
        },
        float: false,
        unsigned: unsigned(t),
    })
}

/// `` `x` and (`w` + `x`) must both be greater than or equal to `0` and less than
/// or equal to the width of the specified `sub` of `image` `` (an offset and an
/// extent of a copy), and `` `offsets[0].x` and `offsets[1].x` must both be ... ``
/// (the corners of a blit): a region inside one mip level of an image.
pub(super) fn inside_req(input: &Input, text: &str) -> Option<Pred> {
    static R: OnceLock<[Regex; 2]> = OnceLock::new();
    let [sum, pair] = R.get_or_init(|| {
        const TAIL: &str = r" must both be greater than or equal to `0` and less than or equal to the (width|height|depth) of the specified `([\w.\[\]]+)` of `(\w+)`$";
        [
            Regex::new(&format!(
                r"^`([\w.\[\]]+)` and \(`?([\w.\[\]]+)`? \+ `([\w.\[\]]+)`\){TAIL}"
            )),
            Regex::new(&format!(r"^`([\w.\[\]]+)` and `([\w.\[\]]+)`{TAIL}")),
        ]
        .map(|r| r.expect("recogniser pattern"))
    });
    // (first, second, whether the second is `first + second`, dim, sub, image)
    let (a, b, summed, rest) = if let Some(c) = whole(sum, text) {
        (c[0] == c[2]).then_some(())?;
        (c[0].clone(), c[1].clone(), true, c[3..].to_vec())
    } else {
        let c = whole(pair, text)?;
        (c[0].clone(), c[1].clone(), false, c[2..].to_vec())
    };
    let [dim, sub, image] = rest.as_slice() else {
        return None;
    };
    (object(input, image)? == Object::Image).then_some(())?;
    let level = format!("{sub}.mipLevel");
    (member(input, &level)?.type_name == "uint32_t").then_some(())?;
    let whole_number = |p: &str| {
        let t = &member(input, p)?.type_name;
        (numeric(t) && t != "float").then(|| unsigned(t))
    };
    let (ua, ub) = (whole_number(&a)?, whole_number(&b)?);
    let extent = Rhs::Extent {
        handle: image.clone(),
        dim: dim.clone(),
        level,
    };
    let cmp = |m: &str, plus: Option<&str>, op: Op, rhs: Rhs, unsigned: bool| Pred::Compare {
        member: m.to_owned(),
        plus: plus.map(str::to_owned),
        op,
        rhs,
        float: false,
        unsigned,
    };
    let zero = || Rhs::Const("0".to_owned());
    // The second value is `b + a` for a copy, `b` for a blit.
    let (second, plus, u2) = if summed {
        (a.as_str(), Some(b.as_str()), false)
    } else {
        (b.as_str(), None, ub)
    };
    Some(Pred::All(vec![
        cmp(&a, None, Op::Ge, zero(), ua),
        cmp(second, plus, Op::Ge, zero(), u2),
        cmp(&a, None, Op::Le, extent.clone(), ua),
        cmp(second, plus, Op::Le, extent, u2),
    ]))
}

/// Whether a C type is an unsigned integer.
pub fn unsigned(c_type: &str) -> bool {
    matches!(c_type, "uint32_t" | "uint64_t" | "VkDeviceSize" | "size_t")
}

/// Whether a C type is a number the checks can compare.
pub fn numeric(c_type: &str) -> bool {
    matches!(
        c_type,
        "uint32_t" | "int32_t" | "uint64_t" | "int64_t" | "VkDeviceSize" | "size_t" | "float"
    )
}
