//! Image layouts, followed as the device will see them.
//!
//! Every command that names the layout of an image's subresources (a copy's
//! `srcImageLayout`, a barrier's `oldLayout`, an attachment's `initialLayout`)
//! requires them to be in that layout when it executes, and the specification
//! leaves what a command does with an image in another layout undefined. A
//! recording knows the layouts its own commands leave behind ([`Recording`]); what it
//! needs from before its start it lists, with the rule that needs it. Each
//! submission compares those lists with the layouts the submissions before it
//! left ([`Overlay`]), in submission order, and records the layouts it leaves in
//! turn: the order in which a queue executes its submissions.

use crate::state::{ImageRecord, Live};
use crate::{Error, Result};
use ash::vk::{self, Handle as _};
use smallvec::{smallvec, SmallVec};
// Looked up on every command that names an image layout: a fast hash for handles.
use super::small_map::SmallMap;

/// A subresource whose layout the recording has not yet set or needed.
const UNKNOWN: vk::ImageLayout = vk::ImageLayout::from_raw(i32::MIN);

/// How an image's subresources are numbered: by aspect, then mip level, then
/// array layer.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Shape {
    /// The aspects with a layout of their own (COLOR; DEPTH and STENCIL; or one
    /// per plane), in numbering order.
    aspects: [vk::ImageAspectFlags; 3],
    /// How many of `aspects` the image has.
    count: u8,
    mips: u32,
    layers: u32,
}

impl Shape {
    /// The subresources of an image made with `record`.
    pub(crate) fn of(record: &ImageRecord) -> Shape {
        let has = crate::formats::aspects(record.format).unwrap_or(vk::ImageAspectFlags::COLOR);
        let mut aspects = [vk::ImageAspectFlags::empty(); 3];
        let mut count = 0;
        for a in [
            vk::ImageAspectFlags::PLANE_0,
            vk::ImageAspectFlags::PLANE_1,
            vk::ImageAspectFlags::PLANE_2,
            vk::ImageAspectFlags::DEPTH,
            vk::ImageAspectFlags::STENCIL,
        ] {
            if has.contains(a) {
                aspects[count] = a;
                count += 1;
            }
        }
        if count == 0 {
            aspects[0] = vk::ImageAspectFlags::COLOR;
            count = 1;
        }
        // The layers of a 3D image are its depth slices, which share one layout.
        let layers = if record.image_type == vk::ImageType::TYPE_3D {
            1
        } else {
            record.array_layers
        };
        Shape {
            aspects,
            count: count as u8,
            mips: record.mip_levels.max(1),
            layers: layers.max(1),
        }
    }

    /// How many subresources the image has.
    pub(crate) fn len(&self) -> usize {
        self.count as usize * self.mips as usize * self.layers as usize
    }

    /// The indices of the subresources `sel` names, clipped to the image (a range
    /// past the image is another rule's to refuse).
    pub(crate) fn indices(&self, sel: &Sel) -> Indices {
        let planes = vk::ImageAspectFlags::PLANE_0
            | vk::ImageAspectFlags::PLANE_1
            | vk::ImageAspectFlags::PLANE_2;
        let mut aspects = 0u8;
        for a in 0..self.count as usize {
            let own = self.aspects[a];
            // COLOR names every plane of a multi-planar image.
            if sel.aspect.intersects(own)
                || (sel.aspect.contains(vk::ImageAspectFlags::COLOR) && own.intersects(planes))
            {
                aspects |= 1 << a;
            }
        }
        let layers = if self.layers == 1 {
            (0, 1)
        } else {
            (sel.layers.0.min(self.layers), sel.layers.1.min(self.layers))
        };
        let mips = (sel.mips.0.min(self.mips), sel.mips.1.min(self.mips));
        Indices {
            aspects,
            levels: self.mips as usize,
            count: self.layers as usize,
            mips,
            layers,
            at: (0, mips.1, layers.1),
        }
    }
}

/// The indices of some subresources of an image ([`Shape::indices`]): aspect by
/// aspect, then level by level, layer by layer. A plain counter: the recorder asks
/// on every command that touches an image.
pub(crate) struct Indices {
    /// The aspects (by their place in the shape) not visited yet, as bits.
    aspects: u8,
    /// The image's mip levels and array layers.
    levels: usize,
    count: usize,
    /// The levels and layers named, clipped to the image (`start..end`).
    mips: (u32, u32),
    layers: (u32, u32),
    /// The aspect, level and layer of the next index.
    at: (usize, u32, u32),
}

impl Iterator for Indices {
    type Item = usize;

    fn next(&mut self) -> Option<usize> {
        loop {
            let (a, m, l) = self.at;
            if m < self.mips.1 {
                if l < self.layers.1 {
                    self.at.2 += 1;
                    return Some((a * self.levels + m as usize) * self.count + l as usize);
                }
                self.at = (a, m + 1, self.layers.0);
                continue;
            }
            if self.aspects == 0 {
                return None;
            }
            let next = self.aspects.trailing_zeros() as usize;
            self.aspects &= self.aspects - 1;
            self.at = (next, self.mips.0, self.layers.0);
        }
    }
}

/// Some subresources of an image: aspects, mip levels and array layers (both as
/// `start..end`).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Sel {
    /// The aspects.
    pub aspect: vk::ImageAspectFlags,
    /// The mip levels.
    pub mips: (u32, u32),
    /// The array layers.
    pub layers: (u32, u32),
}

impl Sel {
    /// Whether two selections name the same subresources.
    pub(crate) fn same(&self, o: &Sel) -> bool {
        self.aspect == o.aspect && self.mips == o.mips && self.layers == o.layers
    }

    /// The subresources of a range, `VK_REMAINING_*` counts reaching the end.
    pub(crate) fn range(r: &vk::ImageSubresourceRange) -> Sel {
        Sel {
            aspect: r.aspect_mask,
            mips: (
                r.base_mip_level,
                r.base_mip_level.saturating_add(r.level_count),
            ),
            layers: (
                r.base_array_layer,
                r.base_array_layer.saturating_add(r.layer_count),
            ),
        }
    }

    /// Whether two selections of one image may share a subresource: their mip and
    /// layer ranges overlap, and their aspects do (`COLOR` names every plane, so it
    /// meets any aspect; a 3D image's view may name layers the image has not, so a
    /// caller comparing views of one is told of overlap it may not have).
    pub(crate) fn overlaps(&self, other: &Sel) -> bool {
        let color = vk::ImageAspectFlags::COLOR;
        let aspects = self.aspect.intersects(other.aspect)
            || self.aspect.contains(color)
            || other.aspect.contains(color);
        aspects
            && self.mips.0 < other.mips.1
            && other.mips.0 < self.mips.1
            && self.layers.0 < other.layers.1
            && other.layers.0 < self.layers.1
    }

    /// The subresources of one mip level a copy names.
    pub(crate) fn layers(r: &vk::ImageSubresourceLayers) -> Sel {
        Sel {
            aspect: r.aspect_mask,
            mips: (r.mip_level, r.mip_level.saturating_add(1)),
            layers: (
                r.base_array_layer,
                r.base_array_layer.saturating_add(r.layer_count),
            ),
        }
    }
}

/// What a recording does to one image's layouts.
#[derive(Clone, Debug)]
struct Track {
    shape: Shape,
    /// For each subresource: the layout the recording needs it in when it starts
    /// (`UNKNOWN`: none), and the rule that needs it. Inline for an image of one
    /// or two subresources (an attachment's), the most a recording per frame tracks.
    first: SmallVec<[(vk::ImageLayout, &'static str); 2]>,
    /// For each subresource: the layout the recording's commands so far leave it
    /// in (`UNKNOWN`: untouched).
    now: SmallVec<[vk::ImageLayout; 2]>,
}

/// The image layouts one recording needs at its start and leaves at its end.
#[derive(Clone, Debug, Default)]
pub(crate) struct Recording {
    images: SmallMap<Track>,
}

/// The error of a subresource found in another layout than a command names.
fn mismatch(
    vuid: &'static str,
    image: u64,
    index: usize,
    named: vk::ImageLayout,
    actual: vk::ImageLayout,
    when: &str,
) -> Error {
    Error::Validation {
        vuid,
        message: format!(
            "a command names layout {named:?} for a subresource (number {index}) of image 0x{image:x}, which is in layout {actual:?} {when}"
        ),
    }
}

impl Recording {
    fn track(&mut self, live: &Live, image: vk::Image) -> Option<&mut Track> {
        self.images.get_or_try_insert(image.as_raw(), || {
            let shape = Shape::of(&live.image(image)?);
            let len = shape.len();
            Some(Track {
                shape,
                first: smallvec![(UNKNOWN, ""); len],
                now: smallvec![UNKNOWN; len],
            })
        })
    }

    /// Refuses `layout` for subresources that the recording's earlier commands
    /// left in another layout (`vuid` names the rule). `UNDEFINED` (a transition
    /// that discards the contents) matches every layout.
    pub(crate) fn check(
        &self,
        image: vk::Image,
        sel: Sel,
        layout: vk::ImageLayout,
        vuid: &'static str,
    ) -> Result<()> {
        if layout == vk::ImageLayout::UNDEFINED {
            return Ok(());
        }
        let Some(t) = self.images.get(image.as_raw()) else {
            return Ok(());
        };
        for i in t.shape.indices(&sel) {
            let now = t.now[i];
            if now != UNKNOWN && now != layout {
                return Err(mismatch(
                    vuid,
                    image.as_raw(),
                    i,
                    layout,
                    now,
                    "after the earlier commands of the recording",
                ));
            }
        }
        Ok(())
    }

    /// The one layout the recording's commands so far leave every one of `sel`'s
    /// subresources in, if it knows one (`None` where one is untouched or they
    /// differ).
    pub(crate) fn known(&self, image: vk::Image, sel: &Sel) -> Option<vk::ImageLayout> {
        let t = self.images.get(image.as_raw())?;
        let mut indices = t.shape.indices(sel);
        let first = t.now[indices.next()?];
        (first != UNKNOWN && indices.all(|i| t.now[i] == first)).then_some(first)
    }

    /// A command needs the subresources in `layout` when it executes (`vuid`
    /// names the rule): those the recording has not touched need it at its start.
    pub(crate) fn require(
        &mut self,
        live: &Live,
        image: vk::Image,
        sel: Sel,
        layout: vk::ImageLayout,
        vuid: &'static str,
    ) {
        if layout == vk::ImageLayout::UNDEFINED {
            return;
        }
        let Some(t) = self.track(live, image) else {
            return;
        };
        let Track { shape, first, now } = t;
        for i in shape.indices(&sel) {
            if now[i] == UNKNOWN {
                first[i] = (layout, vuid);
                now[i] = layout;
            }
        }
    }

    /// A command leaves the subresources in `layout`.
    pub(crate) fn set(&mut self, live: &Live, image: vk::Image, sel: Sel, layout: vk::ImageLayout) {
        let Some(t) = self.track(live, image) else {
            return;
        };
        let Track { shape, now, .. } = t;
        for i in shape.indices(&sel) {
            now[i] = layout;
        }
    }

    /// Refuses to execute `other` (a secondary) after this recording's commands
    /// where it needs a layout they leave otherwise.
    pub(crate) fn check_then(&self, other: &Recording) -> Result<()> {
        for (image, theirs) in &other.images {
            let Some(ours) = self.images.get(*image) else {
                continue;
            };
            for (i, (need, vuid)) in theirs.first.iter().enumerate() {
                let now = ours.now.get(i).copied().unwrap_or(UNKNOWN);
                if *need != UNKNOWN && now != UNKNOWN && now != *need {
                    return Err(mismatch(
                        vuid,
                        *image,
                        i,
                        *need,
                        now,
                        "after the commands recorded before the secondary that names it",
                    ));
                }
            }
        }
        Ok(())
    }

    /// This recording executes `other` (a secondary) after its commands so far.
    pub(crate) fn then(&mut self, other: &Recording) {
        for (image, theirs) in &other.images {
            let ours = self.images.get_or_insert_with(*image, || Track {
                shape: theirs.shape,
                first: smallvec![(UNKNOWN, ""); theirs.now.len()],
                now: smallvec![UNKNOWN; theirs.now.len()],
            });
            for (i, need) in theirs.first.iter().enumerate() {
                if need.0 != UNKNOWN && ours.now[i] == UNKNOWN {
                    ours.first[i] = *need;
                }
            }
            for (i, now) in theirs.now.iter().enumerate() {
                if *now != UNKNOWN {
                    ours.now[i] = *now;
                }
            }
        }
    }

    /// Whether the recording names no image layout.
    pub(crate) fn is_empty(&self) -> bool {
        self.images.is_empty()
    }
}

/// The layouts a run of submissions leaves, over those the device's earlier
/// submissions left: checked and applied one recording at a time, and written to
/// the device only once the submission is made.
pub(crate) struct Overlay<'a> {
    live: &'a Live,
    images: SmallMap<super::image::ImageLayouts>,
}

impl<'a> Overlay<'a> {
    /// No submission yet, over the device's layouts.
    pub(crate) fn new(live: &'a Live) -> Self {
        Overlay {
            live,
            images: SmallMap::default(),
        }
    }

    fn layouts(&mut self, image: u64, len: usize) -> &mut super::image::ImageLayouts {
        let live = self.live;
        self.images
            .get_or_insert_with(image, || live.image_layouts(image, len))
    }

    /// Refuses a recording that needs a layout the submissions before it leave
    /// otherwise.
    pub(crate) fn check(&mut self, recording: &Recording) -> Result<()> {
        for (image, t) in &recording.images {
            let layouts = self.layouts(*image, t.now.len());
            for (i, (need, vuid)) in t.first.iter().enumerate() {
                let actual = layouts[i];
                if *need != UNKNOWN && actual != *need {
                    return Err(mismatch(
                        vuid,
                        *image,
                        i,
                        *need,
                        actual,
                        "when the submission executes it (in the layout the earlier submissions leave)",
                    ));
                }
            }
        }
        Ok(())
    }

    /// The layouts after `recording` executes.
    pub(crate) fn apply(&mut self, recording: &Recording) {
        for (image, t) in &recording.images {
            let layouts = self.layouts(*image, t.now.len());
            for (i, now) in t.now.iter().enumerate() {
                if *now != UNKNOWN {
                    layouts[i] = *now;
                }
            }
        }
    }

    /// The submission was made: the device's layouts are this overlay's.
    pub(crate) fn commit(self) {
        for (image, layouts) in self.images {
            self.live.set_image_layouts(image, layouts);
        }
    }
}

/// Refuses an image whose subresources are not all in one of `layouts` as the
/// device's submissions so far leave them (`vuid` names the rule).
#[cfg_attr(not(feature = "khr_swapchain"), allow(dead_code))]
pub(crate) fn check_device_layout(
    live: &Live,
    image: vk::Image,
    layouts: &[vk::ImageLayout],
    vuid: &'static str,
) -> Result<()> {
    let Some(record) = live.image(image) else {
        return Ok(());
    };
    let len = Shape::of(&record).len();
    for (i, actual) in live.image_layouts(image.as_raw(), len).iter().enumerate() {
        if !layouts.contains(actual) {
            return Err(mismatch(
                vuid,
                image.as_raw(),
                i,
                layouts[0],
                *actual,
                "as the submissions so far leave it",
            ));
        }
    }
    Ok(())
}
