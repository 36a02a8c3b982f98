//! Renders the checks of explicit rules that the recognisers read
//! ([`crate::validity::explicit`]): `if when && broken { fail }` over the checked
//! struct `v`, the scope `s` (features, limits) and nothing else.

use crate::names::field_ident;
use crate::validity::explicit::{Check, FormatClass, Object, Op, Pred, Recognised, Rhs};
use proc_macro2::{Literal, TokenStream};
use quote::quote;

/// A member path (`extent.width`) of `v`, of a command's parameter, or (`array[].x`)
/// of the element `e` a rule is checked on; `offsets[1].x` indexes a fixed-size
/// array.
pub fn member(path: &str, on_command: bool) -> TokenStream {
    let (head, rest) = match path.split_once("[].") {
        Some((_, rest)) => (quote!(e), rest),
        None if on_command => {
            let (first, rest) = path.split_once('.').unwrap_or((path, ""));
            let p = crate::names::ident(&crate::names::param(first));
            (quote!(#p), rest)
        }
        None => (quote!(v), path),
    };
    let rest = rest
        .split('.')
        .filter(|p| !p.is_empty())
        .map(|p| match p.split_once('[') {
            Some((name, index)) => {
                let f = field_ident(name);
                let i = Literal::usize_unsuffixed(index.trim_end_matches(']').parse().unwrap_or(0));
                quote!(#f[#i])
            }
            None => {
                let f = field_ident(p);
                quote!(#f)
            }
        });
    quote!(#head #(.#rest)*)
}

/// A number as the text writes it, as a literal of the compared type.
pub fn number(text: &str, float: bool) -> TokenStream {
    crate::validity::explicit::number(text, float)
        .parse()
        .unwrap_or_else(|_| quote!(0))
}

/// A limit of `l` (the device's `VkPhysicalDeviceLimits`), or an element of an
/// array limit: `maxViewportDimensions[0]`.
fn limit(name: &str) -> TokenStream {
    match name.split_once('[') {
        Some((base, index)) => {
            let f = field_ident(base);
            let i = Literal::usize_unsuffixed(index.trim_end_matches(']').parse().unwrap_or(0));
            quote!(l.#f[#i])
        }
        None => {
            let f = field_ident(name);
            quote!(l.#f)
        }
    }
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
            plus: Some(p),
            op: o,
            rhs,
            float,
            ..
        } => {
            // A sum of two whole numbers, compared as `i128` so it cannot overflow; of
            // two floats, as `f64`, where a NaN fails every comparison.
            let sum = {
                let (m, p) = (member(m), member(p));
                if *float {
                    quote!((#m as f64 + #p as f64))
                } else {
                    quote!((#m as i128 + #p as i128))
                }
            };
            let cast = if *float { quote!(f64) } else { quote!(i128) };
            let ot = op(if negated { inverse(*o) } else { *o });
            // An object the wrappers did not make has no record: not known.
            let known = if negated {
                quote!(is_some_and)
            } else {
                quote!(is_none_or)
            };
            match rhs {
                Rhs::Const(c) => {
                    let c = number(c, *float);
                    if *float && negated {
                        quote!((#sum.is_nan() || #sum #ot #c))
                    } else {
                        quote!(#sum #ot #c)
                    }
                }
                Rhs::Member(other) => {
                    let other = member(other);
                    quote!(#sum #ot (#other as #cast))
                }
                Rhs::Limit(l) => {
                    let l = limit(l);
                    if *float && negated {
                        quote!(s.limits().#known(|l| #sum.is_nan() || #sum #ot (#l as #cast)))
                    } else {
                        quote!(s.limits().#known(|l| #sum #ot (#l as #cast)))
                    }
                }
                Rhs::Created {
                    handle: h,
                    object,
                    field,
                } => {
                    let record = record(h, *object, on_command);
                    let f = field_ident(field);
                    quote!(#record.#known(|r| #sum #ot (r.#f as i128)))
                }
                Rhs::Extent { handle, dim, level } => {
                    let record = record(handle, Object::Image, on_command);
                    let e = level_extent(dim, &member(level));
                    quote!(#record.#known(|r| #sum #ot #e))
                }
            }
        }
        Pred::Compare {
            member: m,
            op: o,
            rhs: Rhs::Extent { handle, dim, level },
            ..
        } => {
            let m = member(m);
            let ot = op(if negated { inverse(*o) } else { *o });
            let record = record(handle, Object::Image, on_command);
            let e = level_extent(dim, &member(level));
            if negated {
                quote!(#record.is_some_and(|r| (#m as i128) #ot #e))
            } else {
                quote!(#record.is_none_or(|r| (#m as i128) #ot #e))
            }
        }
        Pred::Compare {
            member: m,
            op: o,
            rhs,
            float,
            unsigned,
            ..
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
                    let l = limit(l);
                    let n = nan(&m);
                    let cmp = quote!((#m as #cast) #ot (#l as #cast));
                    if negated {
                        quote!(#n s.limits().is_some_and(|l| #cmp))
                    } else {
                        quote!(s.limits().is_none_or(|l| #cmp))
                    }
                }
                // Read above, with a level.
                Rhs::Extent { .. } => quote!(false),
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
        Pred::AbsAtMost { member: m, rhs } => {
            let m = member(m);
            let l = match rhs {
                Rhs::Limit(l) => limit(l),
                _ => quote!(0.0),
            };
            // A NaN is at most nothing.
            if negated {
                quote!(s.limits().is_some_and(|l| (#m as f64).is_nan() || (#m as f64).abs() > #l as f64))
            } else {
                quote!(s.limits().is_none_or(|l| (#m as f64).abs() <= #l as f64))
            }
        }
        Pred::MultipleOf { member: m, rhs } => {
            let m = member(m);
            let is = match rhs {
                // The recogniser reads only a constant above 0.
                Rhs::Const(c) => {
                    let c = number(c, false);
                    return if negated {
                        quote!(#m % #c != 0)
                    } else {
                        quote!(#m % #c == 0)
                    };
                }
                // A limit of 0 has 0 alone as a multiple.
                _ => {
                    let l = match rhs {
                        Rhs::Limit(l) => field_ident(l),
                        _ => field_ident("minMemoryMapAlignment"),
                    };
                    quote!((#m as i128).checked_rem(l.#l as i128).map_or(#m == 0, |r| r == 0))
                }
            };
            if negated {
                quote!(s.limits().is_some_and(|l| !#is))
            } else {
                quote!(s.limits().is_none_or(|l| #is))
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
        Pred::Feature {
            name,
            core,
            enabled,
        } => {
            let f = field_ident(name);
            let core = proc_macro2::Ident::new(core, proc_macro2::Span::call_site());
            if *enabled != negated {
                quote!(s.feature(|f| f.#core.#f))
            } else {
                quote!(!s.feature(|f| f.#core.#f))
            }
        }
        Pred::ImageType { handle, values } => {
            let record = record(handle, Object::Image, on_command);
            let pats = values.iter().map(|v| Literal::i64_unsuffixed(v.number));
            let is = quote!(matches!(r.image_type.as_raw(), #(#pats)|*));
            // An image the wrappers did not make has no record: the condition is not
            // known to hold.
            if negated {
                quote!(#record.is_none_or(|r| !#is))
            } else {
                quote!(#record.is_some_and(|r| #is))
            }
        }
        Pred::FormatIs { member: m, class } => {
            let m = member(m);
            let (color, depth, stencil) = (
                quote!(a.contains(vk::ImageAspectFlags::COLOR)),
                quote!(a.contains(vk::ImageAspectFlags::DEPTH)),
                quote!(a.contains(vk::ImageAspectFlags::STENCIL)),
            );
            let holds = match class {
                FormatClass::Color => quote!(!#depth && !#stencil),
                FormatClass::DepthStencil => quote!(#depth || #stencil),
                FormatClass::DepthOnly => quote!(#depth && !#stencil),
                FormatClass::StencilOnly => quote!(#stencil && !#depth),
                FormatClass::DepthAndStencil => quote!(#depth && #stencil),
                FormatClass::ColorOrDepth => quote!(#color || #depth),
                FormatClass::Stencil => quote!(#stencil),
            };
            // A format the registry does not describe (`UNDEFINED`) is of no kind.
            if negated {
                quote!(crate::formats::aspects(#m).is_none_or(|a| !(#holds)))
            } else {
                quote!(crate::formats::aspects(#m).is_some_and(|a| #holds))
            }
        }
        Pred::AspectsIn { member: m, handle } => {
            let m = member(m);
            let record = record(handle, Object::Image, on_command);
            let extra = quote!((#m.as_raw() & !a.as_raw()));
            // An image the wrappers did not make, or of a format the registry does not
            // describe, is not known.
            if negated {
                quote!(#record.and_then(|r| crate::formats::aspects(r.format)).is_some_and(|a| #extra != 0))
            } else {
                quote!(#record.and_then(|r| crate::formats::aspects(r.format)).is_none_or(|a| #extra == 0))
            }
        }
        Pred::All(ps) => {
            let each = ps.iter().map(|p| pred(p, negated, on_command));
            if negated {
                quote!((#(#each)||*))
            } else {
                quote!((#(#each)&&*))
            }
        }
    }
}

/// The width, height or depth of mip level `level` of the recorded image `r`, as an
/// `i128`: the extent shifted right by the level, at least 1 (a level past the
/// bits leaves 1, never a panic).
fn level_extent(dim: &str, level: &TokenStream) -> TokenStream {
    let d = field_ident(dim);
    quote!((r.extent.#d.checked_shr(#level).unwrap_or(0).max(1) as i128))
}

/// The check of one recognised rule, run only where the condition validusage.json
/// files it under holds with what the scope enables (a rule for a program without
/// an extension, and its sibling for one with it, are each checked where they
/// apply).
pub fn render(r: &Recognised) -> TokenStream {
    let key = r
        .key
        .as_deref()
        .and_then(|k| crate::model::expr::Expr::parse(k).ok())
        .map(|e| e.simplified());
    match (key, &r.check.each) {
        // A rule about each element: the loop runs only where the rule applies.
        (Some(e), Some(_)) => {
            let check = render_check(r, None);
            let gate = key_gate(&e, true);
            quote!(if #gate { #check })
        }
        // Otherwise the condition joins the check's own.
        (Some(e), None) => render_check(r, Some(key_gate(&e, false))),
        (None, _) => render_check(r, None),
    }
}

/// An expression of validusage.json's key syntax over what the scope enables; a
/// conjunction or disjunction is parenthesised unless it stands alone (`alone`).
fn key_gate(e: &crate::model::expr::Expr, alone: bool) -> TokenStream {
    use crate::model::expr::Expr;
    let joined = match e {
        Expr::Name(n) if n == "core" => return quote!(true),
        Expr::Name(n) => {
            let id = crate::names::ident(&n.to_uppercase());
            return quote!(s.exts.has(origin::#id));
        }
        Expr::Not(e) => {
            let e = key_gate(e, false);
            return quote!(!(#e));
        }
        Expr::All(v) => {
            let v = v.iter().map(|e| key_gate(e, false));
            quote!(#(#v)&&*)
        }
        Expr::Any(v) => {
            let v = v.iter().map(|e| key_gate(e, false));
            quote!(#(#v)||*)
        }
    };
    match alone {
        true => joined,
        false => quote!((#joined)),
    }
}

fn render_check(r: &Recognised, gate: Option<TokenStream>) -> TokenStream {
    let Check { when, must, each } = &r.check;
    let vuid = &r.vuid;
    let broken = match must {
        // Alone in the condition, a conjunction's negation needs no parentheses.
        Pred::All(ps) if when.is_empty() && gate.is_none() => {
            let each = ps.iter().map(|p| pred(p, true, r.on_command));
            quote!(#(#each)||*)
        }
        _ => pred(must, true, r.on_command),
    };
    let when = gate
        .into_iter()
        .chain(when.iter().map(|p| pred(p, false, r.on_command)));
    let members = r.check.members();
    // An element's member is shown with its index: `pRegions[2].srcOffset.x`.
    let shown = members
        .iter()
        .map(|m| format!("`{}` = {{:?}}", m.replacen("[]", "[{}]", 1)))
        .collect::<Vec<_>>()
        .join(", ");
    let test = if members.is_empty() {
        // The rule reads only the records of the objects it names.
        let text = &r.text;
        quote! {
            if #(#when &&)* #broken {
                return refuse(#vuid, #text);
            }
        }
    } else {
        let text = format!("{} ({shown})", r.text.replace('{', "{{").replace('}', "}}"));
        let args = members.iter().map(|m| {
            let value = member(m, r.on_command);
            if m.contains("[]") {
                quote!(i, #value)
            } else {
                value
            }
        });
        quote! {
            if #(#when &&)* #broken {
                return refuse(#vuid, format!(#text, #(#args),*));
            }
        }
    };
    let Some(each) = each else {
        return test;
    };
    let array = if r.on_command {
        let a = crate::names::ident(&crate::names::param(&each.array));
        quote!(#a.iter())
    } else {
        let a = field_ident(&each.array);
        let count = field_ident(each.count.as_deref().unwrap_or_default());
        quote! {
            {
                __safety!("the safe setter stored this array and its count.");
                unsafe { members(v.#a, v.#count) }
            }
            .iter()
        }
    };
    if members.iter().any(|m| m.contains("[]")) {
        quote!(for (i, e) in #array.enumerate() { #test })
    } else {
        quote!(for e in #array { #test })
    }
}

/// `oracle_cases.rs`: the oracle's cases as one `oracle_cases!` invocation, which
/// `tests/oracle.rs` defines; each case is a closure that changes the fixture's
/// value `v` (a struct, or a command's `args::` struct), given the device's
/// limits `l`, and how the fixture makes the objects it names (`o`).
pub fn oracle_file(cases: &[crate::plan::oracle::Case]) -> String {
    use crate::plan::oracle::Assign;
    use std::fmt::Write;
    let mut s = String::from(
        "// @generated by tuff-gen from vk.xml and validusage.json; do not edit. Regenerate: cargo run -p tuff-gen\n\
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
            let on = match c.device {
                crate::plan::oracle::OnDevice::Fixture => "",
                crate::plan::oracle::OnDevice::Bare => " on bare",
                crate::plan::oracle::OnDevice::Full => " on full",
            };
            let _ = writeln!(s, "        {:?}{on} => |v, l, o| {{", c.vuid);
            let path = |m: &str| c.place(m);
            for a in &c.assigns {
                let line = match a {
                    Assign::SetBits { member, ty, bits } => format!(
                        "{} |= vk::{}::from_raw({bits:#x});",
                        path(member),
                        crate::names::type_name(ty)
                    ),
                    Assign::Bits { member, ty, bits } => format!(
                        "{} = vk::{}::from_raw({bits:#x});",
                        path(member),
                        crate::names::type_name(ty)
                    ),
                    Assign::ClearBits { member, ty, bits } => format!(
                        "{} &= !vk::{}::from_raw({bits:#x});",
                        path(member),
                        crate::names::type_name(ty)
                    ),
                    // ash names a `FlagBits` type as its flags type.
                    Assign::Enum { member, ty, value } => format!(
                        "{} = vk::{}::from_raw({value});",
                        path(member),
                        crate::names::type_name(ty).replace("FlagBits", "Flags")
                    ),
                    Assign::Number { member, expr } => format!("{} = {expr};", path(member)),
                    Assign::Increment { member } => format!("{} += 1;", path(member)),
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
                    // The test makes an image of another type whole (a 3D image
                    // has depth).
                    Assign::ImageType { handle, value } => format!(
                        "o.{}.set_type(vk::ImageType::from_raw({value}));",
                        crate::names::param(handle)
                    ),
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
