//! Parsing of the small languages inside vk.xml attributes: `len`, `optional` and
//! `externsync`.

/// One comma-separated part of a `len` attribute.
#[derive(Debug, Clone, PartialEq, Eq, serde::Serialize)]
#[serde(tag = "kind", content = "value", rename_all = "snake_case")]
pub enum LenEntry {
    /// `null-terminated`: a C string.
    NullTerminated,
    /// A constant count, e.g. `1`.
    Number(u64),
    /// A `latexmath:[...]` expression (only the spec can evaluate it).
    Math(String),
    /// Another parameter or member, possibly through a pointer:
    /// `pAllocateInfo->descriptorSetCount` has the parts `pAllocateInfo` and
    /// `descriptorSetCount`.
    Reference(Vec<String>),
}

impl LenEntry {
    /// The first parameter named, if the entry names one.
    pub fn other_param(&self) -> Option<&str> {
        match self {
            LenEntry::Reference(parts) => parts.first().map(String::as_str),
            _ => None,
        }
    }

    /// The reference as the specification writes it in VUIDs (`a::b`).
    pub fn vuid_name(&self) -> Option<String> {
        match self {
            LenEntry::Reference(parts) => Some(parts.join("::")),
            _ => None,
        }
    }
}

/// Split a `len` attribute into its entries. Commas inside `latexmath:[...]` do not
/// split.
pub fn parse_len(len: &str) -> Vec<LenEntry> {
    let mut parts = Vec::new();
    let mut depth = 0i32;
    let mut start = 0;
    for (i, c) in len.char_indices() {
        match c {
            '[' | '{' | '(' => depth += 1,
            ']' | '}' | ')' => depth -= 1,
            ',' if depth == 0 => {
                parts.push(&len[start..i]);
                start = i + 1;
            }
            _ => {}
        }
    }
    parts.push(&len[start..]);
    parts
        .into_iter()
        .map(|p| {
            let p = p.trim();
            if p == "null-terminated" {
                LenEntry::NullTerminated
            } else if let Some(math) = p.strip_prefix("latexmath:") {
                LenEntry::Math(
                    math.trim_start_matches('[')
                        .trim_end_matches(']')
                        .to_owned(),
                )
            } else if let Ok(n) = p.parse() {
                LenEntry::Number(n)
            } else {
                LenEntry::Reference(p.split("->").map(str::to_owned).collect())
            }
        })
        .collect()
}

/// `optional="true,false"` as one flag per level of indirection.
pub fn parse_optional(optional: Option<&str>) -> Vec<bool> {
    optional
        .map(|o| o.split(',').map(|x| x.trim() == "true").collect())
        .unwrap_or_default()
}

/// One entry of an `externsync` attribute.
#[derive(Debug, Clone, PartialEq, Eq, serde::Serialize)]
#[serde(tag = "kind", content = "value", rename_all = "snake_case")]
pub enum ExternSync {
    /// `true`: the whole parameter.
    Whole,
    /// `maybe`: only under conditions that the spec states in prose.
    Maybe,
    /// A member path such as `pBuildInfos[].dstAccelerationStructure`.
    Member(String),
}

/// Split an `externsync` attribute.
pub fn parse_externsync(externsync: &str) -> Vec<ExternSync> {
    externsync
        .split(',')
        .map(str::trim)
        .filter(|s| !s.is_empty() && *s != "false")
        .map(|s| match s {
            "true" => ExternSync::Whole,
            "maybe" => ExternSync::Maybe,
            path => ExternSync::Member(path.to_owned()),
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn len_forms() {
        assert_eq!(
            parse_len("enabledLayerCount,null-terminated"),
            [
                LenEntry::Reference(vec!["enabledLayerCount".into()]),
                LenEntry::NullTerminated
            ]
        );
        let deref = parse_len("pAllocateInfo->descriptorSetCount");
        assert_eq!(deref[0].other_param(), Some("pAllocateInfo"));
        assert_eq!(
            deref[0].vuid_name().as_deref(),
            Some("pAllocateInfo::descriptorSetCount")
        );
        assert_eq!(parse_len("geometryCount,1")[1], LenEntry::Number(1));
        assert!(matches!(
            parse_len(r"latexmath:[\lceil{\mathit{samples} \over 32}\rceil]")[..],
            [LenEntry::Math(_)]
        ));
    }

    #[test]
    fn optional_and_externsync() {
        assert_eq!(parse_optional(Some("false,true")), [false, true]);
        assert!(parse_optional(None).is_empty());
        assert_eq!(
            parse_externsync("true,pInfos[].dst"),
            [ExternSync::Whole, ExternSync::Member("pInfos[].dst".into())]
        );
    }
}
