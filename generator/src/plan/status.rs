//! Commands with more than one success code return a typed status, one enum per set
//! of codes (`vkWaitForFences` and `vkWaitSemaphores` share `SuccessOrTimeout`), so
//! that a caller matches on `Timeout` rather than compares a `vk::Result`, and a
//! timeout cannot pass for `Ok(())`. `VK_INCOMPLETE` is not among them: the
//! enumerations that return it call again until they have every element.

use crate::model::Model;
use heck::ToUpperCamelCase;
use std::collections::BTreeMap;

/// The status enum of one set of success codes.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Status {
    /// The enum's name: the variants in the registry's order, the last joined by
    /// `Or` (`SuccessOrTimeout`, `EventSetOrEventReset`).
    pub name: String,
    /// One per code: its variant, the `vk::Result` constant ash names it by, and
    /// the registry's name.
    pub variants: Vec<Variant>,
    /// The emitted commands that return it, in name order.
    pub commands: Vec<String>,
}

/// One success code of a [`Status`].
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Variant {
    /// `Timeout` for `VK_TIMEOUT`, `Suboptimal` for `VK_SUBOPTIMAL_KHR`.
    pub variant: String,
    /// The `vk::Result` constant: `TIMEOUT`, `PIPELINE_COMPILE_REQUIRED` (ash
    /// spells a promoted code by its core name).
    pub constant: String,
    /// `VK_TIMEOUT`.
    pub code: String,
}

/// The success codes of a command that returns `VkResult`, when there is more than
/// one that a caller must tell apart; `None` otherwise.
pub fn codes(model: &Model, command: &str) -> Option<Vec<String>> {
    let cmd = model.commands.get(command)?;
    if cmd.return_type != "VkResult" {
        return None;
    }
    let codes: Vec<String> = cmd
        .successcodes
        .as_deref()
        .unwrap_or("VK_SUCCESS")
        .split(',')
        .filter(|c| *c != "VK_INCOMPLETE")
        .map(str::to_owned)
        .collect();
    codes.iter().any(|c| c != "VK_SUCCESS").then_some(codes)
}

/// The status enum of `command`, if it has one. A code the emitted API's
/// `VkResult` lacks (one ash does not define) is left out: a driver that returns
/// it gets `Error::Vk`, as for any code outside the set.
pub fn of(model: &Model, command: &str) -> Option<Status> {
    let codes = codes(model, command)?;
    let results = model.enum_values.get("VkResult");
    let known = |code: &String| {
        let number = model.enum_numbers.get(code);
        number.is_some()
            && results
                .into_iter()
                .flatten()
                .any(|n| model.enum_numbers.get(n) == number)
    };
    let codes: Vec<&String> = codes.iter().filter(|c| known(c)).collect();
    if codes.len() < 2 {
        return None;
    }
    let variants: Vec<Variant> = codes
        .iter()
        .map(|code| {
            let bare = code.strip_prefix("VK_").unwrap_or(code);
            let bare = ["_KHR", "_EXT"]
                .iter()
                .find_map(|s| bare.strip_suffix(s))
                .unwrap_or(bare);
            // ash has the core name of a promoted code and no alias for it: the
            // shortest name of the same value.
            let number = model.enum_numbers.get(code.as_str());
            let constant = results
                .into_iter()
                .flatten()
                .filter(|n| number.is_some() && model.enum_numbers.get(*n) == number)
                .min_by_key(|n| n.len())
                .unwrap_or(code);
            Variant {
                variant: bare.to_upper_camel_case(),
                constant: constant.strip_prefix("VK_").unwrap_or(constant).to_owned(),
                code: code.to_string(),
            }
        })
        .collect();
    let mut name = String::new();
    for (i, v) in variants.iter().enumerate() {
        if i + 1 == variants.len() {
            name.push_str("Or");
        }
        name.push_str(&v.variant);
    }
    Some(Status {
        name,
        variants,
        commands: vec![command.to_owned()],
    })
}

/// Every status enum the emitted `commands` return, by name.
pub fn all<'a>(model: &Model, commands: impl IntoIterator<Item = &'a str>) -> Vec<Status> {
    let mut out: BTreeMap<String, Status> = BTreeMap::new();
    for command in commands {
        if let Some(s) = of(model, command) {
            out.entry(s.name.clone())
                .and_modify(|e| e.commands.push(command.to_owned()))
                .or_insert(s);
        }
    }
    out.into_values().collect()
}
