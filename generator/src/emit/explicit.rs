//! Renders the checks of explicit rules that the recognisers read
//! ([`crate::validity::explicit`]): `if when && broken { fail }` over the checked
//! struct `v`, the scope `s` (features, limits) and nothing else.

use crate::names::field_ident;
use crate::validity::explicit::{Check, Object, Op, Pred, Recognised, Rhs};
use proc_macro2::{Literal, TokenStream};
use quote::quote;

/// A member path (`extent.width`) of `v`, or of a command's parameter.
pub fn member(path: &str, on_command: bool) -> TokenStream {
    let mut parts = path.split('.');
    let head = if on_command {
        let p = crate::names::ident(&crate::names::param(parts.next().unwrap_or_default()));
        quote!(#p)
    } else {
        quote!(v)
    };
    let rest = parts.map(field_ident);
    quote!(#head #(.#rest)*)
}

/// A number as the text writes it, as a literal of the compared type.
pub fn number(text: &str, float: bool) -> TokenStream {
    crate::validity::explicit::number(text, float)
        .parse()
        .unwrap_or_else(|_| quote!(0))
}

fn op(o: Op) -> TokenStream {
    match o {
        Op::Lt => quote!(<),
        Op::Le => quote!(<=),
        Op::Gt => quote!(>),
        Op::Ge => quote!(>=),
        Op::Eq => quote!(==),
        Op::Ne => quote!(!=),
    }
}

use crate::validity::explicit::is_bool;

/// The device's record of the object a handle names: `Option<BufferRecord>` or
/// `Option<ImageRecord>`.
fn record(path: &str, object: Object, on_command: bool) -> TokenStream {
    let raw = if on_command {
        let h = member(path, true);
        quote!(#h.raw())
    } else {
        member(path, false)
    };
    match object {
        Object::Buffer => quote!(s.buffer(#raw)),
        Object::Image => quote!(s.image(#raw)),
    }
}

/// The comparison that fails exactly when `o` holds (for numbers that compare).
fn inverse(o: Op) -> Op {
    match o {
        Op::Lt => Op::Ge,
        Op::Le => Op::Gt,
        Op::Gt => Op::Le,
        Op::Ge => Op::Lt,
        Op::Eq => Op::Ne,
        Op::Ne => Op::Eq,
    }
}

/// A predicate as a `bool` expression; with `negated`, the expression that holds
/// exactly when the predicate does not (a NaN never satisfies a comparison).
fn pred(p: &Pred, negated: bool, on_command: bool) -> TokenStream {
    let member = |m: &str| member(m, on_command);
    match p {
        Pred::AnyBit { member: m, bits } | Pred::NoBit { member: m, bits } => {
            let mask = bits.iter().fold(0u64, |acc, b| acc | b.number as u64);
            let mask = Literal::u64_unsuffixed(mask);
            let m = member(m);
            if matches!(p, Pred::AnyBit { .. }) != negated {
                quote!((#m.as_raw() & #mask) != 0)
            } else {
                quote!((#m.as_raw() & #mask) == 0)
            }
        }
        Pred::OneOf { member: m, values } | Pred::NoneOf { member: m, values } => {
            let m = if is_bool(values) {
                member(m)
            } else {
                let m = member(m);
                quote!(#m.as_raw())
            };
            let mut numbers: Vec<i64> = values.iter().map(|v| v.number).collect();
            numbers.sort_unstable();
            numbers.dedup();
            let pats = ranges(&numbers).into_iter().map(|(a, b)| {
                let (la, lb) = (Literal::i64_unsuffixed(a), Literal::i64_unsuffixed(b));
                if a == b {
                    quote!(#la)
                } else if a + 1 == b {
                    quote!(#la | #lb)
                } else {
                    quote!(#la..=#lb)
                }
            });
            if matches!(p, Pred::OneOf { .. }) != negated {
                quote!(matches!(#m, #(#pats)|*))
            } else {
                quote!(!matches!(#m, #(#pats)|*))
            }
        }
        Pred::Compare {
            member: m,
            op: o,
            rhs,
            float,
            unsigned,
        } => {
            let m = member(m);
            let mut o = if negated { inverse(*o) } else { *o };
            // `x <= 0` of an unsigned `x` is `x == 0`.
            if *unsigned && o == Op::Le && matches!(rhs, Rhs::Const(c) if c == "0") {
                o = Op::Eq;
            }
            let ot = op(o);
            let nan = |x: &TokenStream| {
                if *float && negated {
                    quote!((#x as f64).is_nan() ||)
                } else {
                    quote!()
                }
            };
            let cast = if *float { quote!(f64) } else { quote!(i128) };
            match rhs {
                Rhs::Const(c) => {
                    let c = number(c, *float);
                    let n = nan(&m);
                    quote!(#n #m #ot #c)
                }
                Rhs::Member(other) => {
                    let other = member(other);
                    let (n1, n2) = (nan(&m), nan(&other));
                    quote!(#n1 #n2 (#m as #cast) #ot (#other as #cast))
                }
                Rhs::Limit(l) => {
                    let l = field_ident(l);
                    let n = nan(&m);
                    let cmp = quote!((#m as #cast) #ot (l.#l as #cast));
                    if negated {
                        quote!(#n s.limits().is_some_and(|l| #cmp))
                    } else {
                        quote!(s.limits().is_none_or(|l| #cmp))
                    }
                }
                Rhs::Created {
                    handle: h,
                    object,
                    field,
                } => {
                    let record = record(h, *object, on_command);
                    let f = field_ident(field);
                    let cmp = quote!((#m as #cast) #ot (r.#f as #cast));
                    // An object the wrappers did not make has no record: not known.
                    if negated {
                        quote!(#record.is_some_and(|r| #cmp))
                    } else {
                        quote!(#record.is_none_or(|r| #cmp))
                    }
                }
            }
        }
        Pred::Usage {
            handle: h,
            object,
            bits,
        } => {
            let record = record(h, *object, on_command);
            let mask = Literal::u64_unsuffixed(bits.iter().fold(0u64, |a, b| a | b.number as u64));
            if negated {
                quote!(#record.is_some_and(|r| (u64::from(r.usage.as_raw()) & #mask) != #mask))
            } else {
                quote!(#record.is_none_or(|r| (u64::from(r.usage.as_raw()) & #mask) == #mask))
            }
        }
        Pred::Bound { handle: h, object } => {
            let record = record(h, *object, on_command);
            // `SPARSE_BINDING` is bit 0 of both objects' create flags.
            let bound = quote!((r.bound || (r.flags.as_raw() & 1) != 0));
            if negated {
                quote!(#record.is_some_and(|r| !#bound))
            } else {
                quote!(#record.is_none_or(|r| #bound))
            }
        }
        Pred::Feature { name, enabled } => {
            let f = field_ident(name);
            if *enabled != negated {
                quote!(s.feature(|f| f.#f))
            } else {
                quote!(!s.feature(|f| f.#f))
            }
        }
    }
}

/// The check of one recognised rule.
pub fn render(r: &Recognised) -> TokenStream {
    let Check { when, must } = &r.check;
    let vuid = &r.vuid;
    let when = when.iter().map(|p| pred(p, false, r.on_command));
    let broken = pred(must, true, r.on_command);
    let members = r.check.members();
    let shown = members
        .iter()
        .map(|m| format!("`{m}` = {{:?}}"))
        .collect::<Vec<_>>()
        .join(", ");
    if members.is_empty() {
        // The rule reads only the records of the objects it names.
        let text = &r.text;
        return quote! {
            if #(#when &&)* #broken {
                return Err(fail(#vuid, #text.into()));
            }
        };
    }
    let text = format!("{} ({shown})", r.text.replace('{', "{{").replace('}', "}}"));
    let args = members.iter().map(|m| member(m, r.on_command));
    quote! {
        if #(#when &&)* #broken {
            return Err(fail(#vuid, format!(#text, #(#args),*)));
        }
    }
}

/// `oracle_cases.rs`: the oracle's cases as one `oracle_cases!` invocation, which
/// `tests/oracle.rs` defines; each case is a closure that changes the fixture's
/// value `v` (a struct, or a command's `args::` struct), given the device's
/// limits `l`, and how the fixture makes the objects it names (`o`).
pub fn oracle_file(cases: &[crate::plan::oracle::Case]) -> String {
    use crate::plan::oracle::{path, Assign};
    use std::fmt::Write;
    let mut s = String::from(
        "// Generated by tuff-gen from vk.xml and validusage.json; do not edit. Regenerate: cargo run -p tuff-gen\n\
         //\n\
         // The oracle's cases: for each explicit rule the recognisers read on a struct that\n\
         // tests/oracle.rs has a fixture for, the change to the fixture's smallest valid\n\
         // value that breaks exactly that rule.\n\
         oracle_cases! {\n",
    );
    let mut items: Vec<&crate::plan::oracle::Case> = Vec::new();
    for c in cases {
        if items.last().is_none_or(|l| l.item != c.item) {
            items.push(c);
        }
    }
    for first in items {
        let item = first.item.as_str();
        let (fixture, ty) = if first.on_command {
            // `vkCmdSetEvent` -> `cmd_set_event: args::CmdSetEvent`.
            let f = crate::names::command_fn(item);
            let t = item.strip_prefix("vk").unwrap_or(item).to_owned();
            (f, format!("args::{t}"))
        } else {
            let lt = if first.lifetime { "<'_>" } else { "" };
            (
                crate::plan::checks::snake(item),
                format!("vk::{}{lt}", crate::names::type_name(item)),
            )
        };
        let _ = writeln!(s, "    {fixture}: {ty} {{");
        for c in cases.iter().filter(|c| c.item == item) {
            let _ = writeln!(s, "        {:?} => |v, l, o| {{", c.vuid);
            let path = |m: &str| path(m, c.on_command);
            for a in &c.assigns {
                let line = match a {
                    Assign::SetBits { member, ty, bits } => format!(
                        "v.{} |= vk::{}::from_raw({bits:#x});",
                        path(member),
                        crate::names::type_name(ty)
                    ),
                    Assign::Bits { member, ty, bits } => format!(
                        "v.{} = vk::{}::from_raw({bits:#x});",
                        path(member),
                        crate::names::type_name(ty)
                    ),
                    Assign::ClearBits { member, ty, bits } => format!(
                        "v.{} &= !vk::{}::from_raw({bits:#x});",
                        path(member),
                        crate::names::type_name(ty)
                    ),
                    // ash names a `FlagBits` type as its flags type.
                    Assign::Enum { member, ty, value } => format!(
                        "v.{} = vk::{}::from_raw({value});",
                        path(member),
                        crate::names::type_name(ty).replace("FlagBits", "Flags")
                    ),
                    Assign::Number { member, expr } => format!("v.{} = {expr};", path(member)),
                    // The fixture makes its objects from `o` after the change, so
                    // the handle's name is the spec's (a parameter as the method
                    // names it).
                    Assign::ClearUsage {
                        handle,
                        object,
                        bits,
                    } => format!(
                        "o.{}.usage &= !vk::{}UsageFlags::from_raw({bits:#x});",
                        crate::names::param(handle),
                        match object {
                            crate::validity::explicit::Object::Buffer => "Buffer",
                            crate::validity::explicit::Object::Image => "Image",
                        }
                    ),
                    Assign::Unbound { handle } => {
                        format!("o.{}.bind = false;", crate::names::param(handle))
                    }
                };
                let _ = writeln!(s, "            {line}");
            }
            s.push_str("        },\n");
        }
        s.push_str("    },\n");
    }
    s.push_str("}\n");
    s
}

/// Sorted values as inclusive ranges of consecutive numbers.
pub(crate) fn ranges(values: &[i64]) -> Vec<(i64, i64)> {
    let mut out: Vec<(i64, i64)> = Vec::new();
    for &v in values {
        match out.last_mut() {
            Some((_, end)) if *end + 1 == v => *end = v,
            _ => out.push((v, v)),
        }
    }
    out
}
