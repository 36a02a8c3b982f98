//! Shader modules from SPIR-V as it is stored in a file: bytes, in either byte order,
//! checked before Vulkan sees them.
//!
//! ```no_run
//! # fn f(device: &tuff::Device, bytes: &[u8]) -> tuff::Result<()> {
//! // SAFETY: the shader promise: `bytes` is this program's own compiled shader,
//! // valid for Vulkan, and it stays inside the resources its pipelines give it.
//! let module = unsafe { device.create_shader_module_from_spirv(bytes) }?;
//! # let _ = module;
//! # Ok(()) }
//! ```
//!
//! Making a shader module is where a program vouches for its shaders, once: the
//! method is `unsafe`, and its `# Safety` section is the promise. Pipelines and the
//! commands that run them check what they can read from the module's interface and
//! the recorded state, and stay safe.

use crate::handles::{Device, ShaderModule};
use crate::structs::ShaderModuleCreateInfo;
use crate::{Error, Result};
use std::collections::HashMap;

/// The first word of every SPIR-V module.
const MAGIC: u32 = 0x0723_0203;

impl Device {
    /// `vkCreateShaderModule` from the bytes of a SPIR-V module (a `.spv` file),
    /// which may be in either byte order. See [`spirv_words`] for what is checked.
    ///
    /// # Safety
    ///
    /// The shader promise of [`Device::create_shader_module`], for the module the
    /// bytes hold.
    pub unsafe fn create_shader_module_from_spirv(&self, bytes: &[u8]) -> Result<ShaderModule> {
        let words = spirv_words(bytes)?;
        // SAFETY: the caller makes the shader promise for these words.
        unsafe { self.create_shader_module(&ShaderModuleCreateInfo::new().code(&words)) }
    }
}

/// The words of the SPIR-V module stored in `bytes`, in the host's byte order.
///
/// Refuses, naming the rule, bytes that are empty
/// (`VUID-VkShaderModuleCreateInfo-codeSize-01085`), not a whole number of words
/// (`VUID-VkShaderModuleCreateInfo-codeSize-01086`), or that do not begin with the
/// SPIR-V magic number in either byte order, so cannot be the SPIR-V that
/// `VUID-VkShaderModuleCreateInfo-pCode-01087` asks for.
///
/// ```
/// let words = tuff::spirv_words(&[0x03, 0x02, 0x23, 0x07, 1, 0, 0, 0]).unwrap();
/// assert_eq!(words, [0x0723_0203, 1]);
/// // The same module stored big-endian.
/// let swapped = tuff::spirv_words(&[0x07, 0x23, 0x02, 0x03, 0, 0, 0, 1]).unwrap();
/// assert_eq!(swapped, words);
/// assert!(tuff::spirv_words(b"#version 450").is_err());
/// ```
pub fn spirv_words(bytes: &[u8]) -> Result<Vec<u32>> {
    let refuse = |vuid: &'static str, message: String| Err(Error::Validation { vuid, message });
    if bytes.is_empty() {
        return refuse(
            "VUID-VkShaderModuleCreateInfo-codeSize-01085",
            "the SPIR-V module is empty".into(),
        );
    }
    if bytes.len() % 4 != 0 {
        return refuse(
            "VUID-VkShaderModuleCreateInfo-codeSize-01086",
            format!(
                "{} bytes of SPIR-V are not a whole number of 4-byte words",
                bytes.len()
            ),
        );
    }
    let mut words: Vec<u32> = bytes
        .chunks_exact(4)
        .map(|w| u32::from_le_bytes([w[0], w[1], w[2], w[3]]))
        .collect();
    match words[0] {
        MAGIC => {}
        swapped if swapped == MAGIC.swap_bytes() => {
            words.iter_mut().for_each(|w| *w = w.swap_bytes());
        }
        other => {
            return refuse(
                "VUID-VkShaderModuleCreateInfo-pCode-01087",
                format!(
                    "the bytes do not begin with the SPIR-V magic number {MAGIC:#010x} \
                     (they begin with {other:#010x}): not a SPIR-V module"
                ),
            );
        }
    }
    Ok(words)
}

/// What kind of descriptor a resource variable reads, from its storage class and
/// type (the specification's table of shader resources and descriptor types).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum ResourceKind {
    /// A `Block` in `Uniform` storage.
    UniformBuffer,
    /// `StorageBuffer` storage, or a `BufferBlock` in `Uniform`.
    StorageBuffer,
    /// `OpTypeSampler`.
    Sampler,
    /// `OpTypeImage` read through a sampler.
    SampledImage,
    /// `OpTypeImage` read and written without one.
    StorageImage,
    /// `OpTypeSampledImage`.
    CombinedImageSampler,
    /// A buffer-dimensioned image read through a sampler.
    UniformTexelBuffer,
    /// A buffer-dimensioned storage image.
    StorageTexelBuffer,
    /// A `SubpassData` image.
    InputAttachment,
    /// Anything else (an acceleration structure, an extension's type): not compared.
    Other,
}

impl ResourceKind {
    /// Whether a descriptor of type `ty` can back a variable of this kind.
    pub(crate) fn accepts(self, ty: ash::vk::DescriptorType) -> bool {
        use ash::vk::DescriptorType as T;
        // A mutable descriptor may hold any type; the caller writes the right one.
        if ty == T::MUTABLE_EXT {
            return true;
        }
        match self {
            ResourceKind::UniformBuffer => matches!(
                ty,
                T::UNIFORM_BUFFER | T::UNIFORM_BUFFER_DYNAMIC | T::INLINE_UNIFORM_BLOCK
            ),
            ResourceKind::StorageBuffer => {
                matches!(ty, T::STORAGE_BUFFER | T::STORAGE_BUFFER_DYNAMIC)
            }
            ResourceKind::Sampler => matches!(ty, T::SAMPLER | T::COMBINED_IMAGE_SAMPLER),
            ResourceKind::SampledImage => {
                matches!(ty, T::SAMPLED_IMAGE | T::COMBINED_IMAGE_SAMPLER)
            }
            ResourceKind::StorageImage => ty == T::STORAGE_IMAGE,
            ResourceKind::CombinedImageSampler => ty == T::COMBINED_IMAGE_SAMPLER,
            ResourceKind::UniformTexelBuffer => ty == T::UNIFORM_TEXEL_BUFFER,
            ResourceKind::StorageTexelBuffer => ty == T::STORAGE_TEXEL_BUFFER,
            ResourceKind::InputAttachment => ty == T::INPUT_ATTACHMENT,
            ResourceKind::Other => true,
        }
    }
}

/// The type of an image variable (`OpTypeImage`, alone or in an
/// `OpTypeSampledImage`), as far as a view bound to it must match it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct ImageShape {
    /// `Dim`: 0 1D, 1 2D, 2 3D, 3 Cube, 4 Rect, 5 Buffer, 6 SubpassData.
    pub dim: u32,
    /// `Arrayed`.
    pub arrayed: bool,
    /// The sampled type, as [`crate::formats::color_numeric`] numbers them: 1
    /// `OpTypeFloat`, 2 `OpTypeInt`, 0 anything else.
    pub numeric: u32,
    /// The `Image Format` operand (0: `Unknown`, read and written in the view's
    /// format).
    pub format: u32,
}

impl ImageShape {
    /// The view type a view read through the variable must have (the
    /// specification's Instruction/Sampler/Image View Validation), for the `Dim`s a
    /// view type names.
    pub(crate) fn view_type(self) -> Option<ash::vk::ImageViewType> {
        use ash::vk::ImageViewType as V;
        Some(match (self.dim, self.arrayed) {
            (0, false) => V::TYPE_1D,
            (0, true) => V::TYPE_1D_ARRAY,
            (1, false) => V::TYPE_2D,
            (1, true) => V::TYPE_2D_ARRAY,
            (2, false) => V::TYPE_3D,
            (3, false) => V::CUBE,
            (3, true) => V::CUBE_ARRAY,
            _ => return None,
        })
    }
}

/// A resource variable a module declares: its set, binding, kind and array size (0
/// for a runtime-sized array).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Resource {
    /// `DescriptorSet`.
    pub set: u32,
    /// `Binding`.
    pub binding: u32,
    /// What descriptor it reads.
    pub kind: ResourceKind,
    /// Descriptors the variable spans: 1, an array's length, or 0 for a runtime array
    /// or one whose length is a specialization constant (the whole binding).
    pub count: u32,
    /// For an image variable, its image type.
    pub image: Option<ImageShape>,
    /// What the module's instructions do with it ([`ops`] bits).
    pub ops: u16,
    /// The fewest components of a texel that `OpImageWrite` writes through it (0:
    /// none is written).
    pub write_components: u8,
    /// Its `InputAttachmentIndex` decoration, if it has one.
    pub input_index: Option<u32>,
}

/// What a module's instructions do with a resource variable, one bit each: read
/// through it by the ones a value or pointer derived from it reaches (loads, access
/// chains, `OpSampledImage`, `OpImage`, copies, selections, phis, and function
/// arguments into parameters). An operation on a value whose variable is not found
/// counts for every image variable of the module.
pub(crate) mod ops {
    /// `OpImageRead` or `OpImageSparseRead`.
    pub const READ: u16 = 1;
    /// `OpImageWrite`.
    pub const WRITE: u16 = 2;
    /// `OpImageTexelPointer`: an atomic operation on a texel.
    pub const ATOMIC: u16 = 4;
    /// A sampling, fetch or gather instruction.
    pub const SAMPLE: u16 = 8;
    /// A sampling or gather instruction with depth comparison.
    pub const DREF: u16 = 16;
    /// An `OpImageSample*` or `OpImageSparseSample*` instruction with `ImplicitLod`,
    /// `Dref` or `Proj` in its name, which a sampler with unnormalized coordinates
    /// cannot serve.
    pub const IMPLICIT_DREF_PROJ: u16 = 32;
    /// An `OpImageSample*` or `OpImageSparseSample*` instruction with a LOD bias or
    /// an offset among its image operands.
    pub const SAMPLE_BIAS_OFFSET: u16 = 64;
    /// Any image instruction with `ConstOffset`, `Offset` or `ConstOffsets`.
    pub const OFFSET: u16 = 128;
    /// Any image instruction other than `OpImageSample*` and `OpImageSparseSample*`
    /// (fetches, gathers, reads, writes, atomics, queries), which an image with a
    /// sampler Y'CbCr conversion cannot serve.
    pub const NOT_SAMPLE: u16 = 256;
    /// A load through a pointer traced to it (`OpLoad`, the source of
    /// `OpCopyMemory`, atomics): how a shader reads a buffer.
    pub const LOAD: u16 = 512;
    /// A store through a pointer traced to it (`OpStore`, the target of
    /// `OpCopyMemory`, atomics that change memory): how a shader writes a buffer.
    pub const STORE: u16 = 1024;
}

/// What a module's shaders need from a pipeline layout: every resource variable it
/// declares with a set and binding, and the bytes of its push-constant block. A
/// module whose entry points do not all use every variable asks for more than the
/// one in a pipeline needs; that errs on the side of refusing.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub(crate) struct Interface {
    /// The resource variables.
    pub resources: Vec<Resource>,
    /// The byte range `start..end` of the push-constant block, if one is declared.
    pub push_constants: Option<(u32, u32)>,
    /// Each vertex entry point's name and the input locations it declares (a
    /// location and how many consecutive ones the variable takes).
    pub vertex_inputs: Vec<(String, Vec<(u32, u32)>)>,
    /// Every entry point, with the execution modes declared for it.
    pub entry_points: Vec<EntryPoint>,
    /// Each specialization constant's `SpecId` and the bytes a map entry gives it
    /// (a boolean's: a `VkBool32`'s four).
    pub spec_constants: Vec<(u32, u32)>,
    /// The capabilities the module declares.
    pub capabilities: Vec<u32>,
}

/// An entry point of a module.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub(crate) struct EntryPoint {
    /// Its name.
    pub name: String,
    /// Its execution model (0 `Vertex`, 1 `TessellationControl`, 2
    /// `TessellationEvaluation`, 3 `Geometry`, 4 `Fragment`, 5 `GLCompute`, ...).
    pub model: u32,
    /// Each `OpExecutionMode` declared for it: the mode and its literal operands.
    pub modes: Vec<(u32, Vec<u32>)>,
    /// The built-in variables of its interface (decorated themselves, or members of
    /// a block, as `gl_PerVertex` is): the `BuiltIn`, the variable's storage class
    /// and its array size (1 for a scalar or vector).
    pub builtins: Vec<(u32, u32, u32)>,
    /// The built-ins the module stores to through its interface's variables.
    pub writes: Vec<u32>,
    /// Its user-defined input and output variables (and the members of such
    /// blocks), the per-vertex array of a tessellation or geometry stage's
    /// variable taken off.
    pub io: Vec<IoVar>,
    /// The members of its built-in input block and of its built-in output block (as
    /// `gl_PerVertex`): each `BuiltIn` with its array size, in declaration order.
    pub builtin_blocks: [Vec<(u32, u32)>; 2],
}

/// A user-defined input or output of an entry point's interface: a variable, or a
/// member of a block variable, with the place it takes in the interface.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct IoVar {
    /// An output (else an input).
    pub output: bool,
    /// Its `Location` (`u32::MAX` where none is found: it matches nothing).
    pub location: u32,
    /// Its `Component`, or 0.
    pub component: u32,
    /// Decorated `Patch` (itself or its block).
    pub patch: bool,
    /// Its type.
    pub ty: IoType,
}

/// The type of an interface variable, as far as interface matching compares it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) enum IoType {
    /// A scalar: its kind (0 float, 1 signed integer, 2 unsigned integer) and bit
    /// width.
    Scalar(u8, u32),
    /// A vector of a scalar type and its component count.
    Vector(Box<IoType>, u32),
    /// A matrix of a column vector type and its column count.
    Matrix(Box<IoType>, u32),
    /// An array of an element type and its length (0: not a plain constant).
    Array(Box<IoType>, u32),
    /// A structure's member types, in order.
    Struct(Vec<IoType>),
    /// Anything else, or what the reader could not follow: it matches nothing.
    Unknown,
}

impl IoType {
    /// Whether an output of this type matches an input of type `input`: the same
    /// type, or with `narrowing` (maintenance4) a vector of more components of the
    /// same component type. A type the reader could not follow matches nothing.
    pub(crate) fn matches(&self, input: &IoType, narrowing: bool) -> bool {
        if !self.known() || !input.known() {
            return false;
        }
        match (self, input) {
            (IoType::Vector(a, n), IoType::Vector(b, m)) if narrowing => a == b && n >= m,
            _ => self == input,
        }
    }

    fn known(&self) -> bool {
        match self {
            IoType::Scalar(..) => true,
            IoType::Vector(t, _) | IoType::Matrix(t, _) => t.known(),
            IoType::Array(t, len) => *len > 0 && t.known(),
            IoType::Struct(members) => members.iter().all(IoType::known),
            IoType::Unknown => false,
        }
    }

    /// The locations it takes: one per scalar or vector (two for a 64-bit vector of
    /// three or four), one per matrix column, times an array's length, summed over
    /// a structure's members.
    pub(crate) fn locations(&self) -> u32 {
        match self {
            IoType::Vector(t, n) if matches!(**t, IoType::Scalar(_, 64)) && *n > 2 => 2,
            IoType::Scalar(..) | IoType::Vector(..) | IoType::Unknown => 1,
            IoType::Matrix(t, n) => n.saturating_mul(t.locations()),
            IoType::Array(t, len) => len.saturating_mul(t.locations()),
            IoType::Struct(members) => members
                .iter()
                .fold(0u32, |sum, t| sum.saturating_add(t.locations())),
        }
    }
}

impl EntryPoint {
    /// The operands of execution mode `mode`, if the entry point declares it.
    pub(crate) fn mode(&self, mode: u32) -> Option<&[u32]> {
        self.modes
            .iter()
            .find(|(m, _)| *m == mode)
            .map(|(_, operands)| operands.as_slice())
    }

    /// The first of `modes` the entry point declares.
    pub(crate) fn first_of(&self, modes: &[u32]) -> Option<u32> {
        self.modes
            .iter()
            .map(|(m, _)| *m)
            .find(|m| modes.contains(m))
    }
}

impl Interface {
    /// The entry point `name` with the execution model of pipeline stage `stage`.
    pub(crate) fn entry_point(
        &self,
        name: &[u8],
        stage: ash::vk::ShaderStageFlags,
    ) -> Option<&EntryPoint> {
        use ash::vk::ShaderStageFlags as S;
        let model = match stage {
            S::VERTEX => 0,
            S::TESSELLATION_CONTROL => 1,
            S::TESSELLATION_EVALUATION => 2,
            S::GEOMETRY => 3,
            S::FRAGMENT => 4,
            S::COMPUTE => 5,
            _ => return None,
        };
        self.entry_points
            .iter()
            .find(|e| e.name.as_bytes() == name && e.model == model)
    }
}

impl Interface {
    /// Whether the vertex entry point `name` declares an input at `location`.
    pub(crate) fn reads_vertex_location(&self, name: &[u8], location: u32) -> bool {
        self.vertex_inputs
            .iter()
            .filter(|(n, _)| n.as_bytes() == name)
            .flat_map(|(_, inputs)| inputs)
            .any(|&(start, count)| location >= start && location - start < count)
    }
}

/// The instructions of a module that the interface reads, by result id.
#[derive(Default)]
struct Module {
    decorations: std::collections::HashMap<(u32, u32), u32>,
    member_decorations: std::collections::HashMap<(u32, u32, u32), u32>,
    /// Member decorations without operands.
    member_flags: std::collections::HashSet<(u32, u32, u32)>,
    /// Result id to (opcode, operands after the result id).
    types: std::collections::HashMap<u32, (u32, Vec<u32>)>,
    constants: std::collections::HashMap<u32, u32>,
    flags: std::collections::HashSet<(u32, u32)>,
}

const OP_TYPE_INT: u32 = 21;
const OP_TYPE_FLOAT: u32 = 22;
const OP_TYPE_VECTOR: u32 = 23;
const OP_TYPE_MATRIX: u32 = 24;
const OP_TYPE_IMAGE: u32 = 25;
const OP_TYPE_SAMPLER: u32 = 26;
const OP_TYPE_SAMPLED_IMAGE: u32 = 27;
const OP_TYPE_ARRAY: u32 = 28;
const OP_TYPE_RUNTIME_ARRAY: u32 = 29;
const OP_TYPE_STRUCT: u32 = 30;
const OP_TYPE_POINTER: u32 = 32;
const DEC_BLOCK: u32 = 2;
const DEC_BUFFER_BLOCK: u32 = 3;
const DEC_ARRAY_STRIDE: u32 = 6;
const DEC_MATRIX_STRIDE: u32 = 7;
const DEC_OFFSET: u32 = 35;

impl Module {
    fn ty(&self, id: u32) -> Option<(u32, &[u32])> {
        self.types.get(&id).map(|(op, w)| (*op, w.as_slice()))
    }

    /// The type under any arrays, with the descriptor count they give.
    fn element(&self, mut id: u32) -> (u32, u32) {
        let mut count = 1u32;
        for _ in 0..8 {
            match self.ty(id) {
                Some((OP_TYPE_ARRAY, [elem, len, ..])) => {
                    // A length that is not a plain constant (a specialization
                    // constant) is not known: 0, as for a runtime array, reaches
                    // the whole binding.
                    count = count.saturating_mul(self.constants.get(len).copied().unwrap_or(0));
                    id = *elem;
                }
                Some((OP_TYPE_RUNTIME_ARRAY, [elem, ..])) => {
                    count = 0;
                    id = *elem;
                }
                _ => break,
            }
        }
        (id, count)
    }

    fn kind(&self, storage: u32, element: u32) -> ResourceKind {
        const UNIFORM_CONSTANT: u32 = 0;
        const UNIFORM: u32 = 2;
        const STORAGE_BUFFER: u32 = 12;
        const DIM_BUFFER: u32 = 5;
        const DIM_SUBPASS_DATA: u32 = 6;
        match (storage, self.ty(element)) {
            (UNIFORM, _) if self.flags.contains(&(element, DEC_BUFFER_BLOCK)) => {
                ResourceKind::StorageBuffer
            }
            (UNIFORM, _) if self.flags.contains(&(element, DEC_BLOCK)) => {
                ResourceKind::UniformBuffer
            }
            (STORAGE_BUFFER, _) => ResourceKind::StorageBuffer,
            (UNIFORM_CONSTANT, Some((OP_TYPE_SAMPLER, _))) => ResourceKind::Sampler,
            (UNIFORM_CONSTANT, Some((OP_TYPE_SAMPLED_IMAGE, _))) => {
                ResourceKind::CombinedImageSampler
            }
            // Operands: sampled type, Dim, Depth, Arrayed, MS, Sampled, format.
            (UNIFORM_CONSTANT, Some((OP_TYPE_IMAGE, [_, dim, _, _, _, sampled, ..]))) => {
                match (*dim, *sampled) {
                    (DIM_BUFFER, 2) => ResourceKind::StorageTexelBuffer,
                    (DIM_BUFFER, _) => ResourceKind::UniformTexelBuffer,
                    (DIM_SUBPASS_DATA, _) => ResourceKind::InputAttachment,
                    (_, 2) => ResourceKind::StorageImage,
                    _ => ResourceKind::SampledImage,
                }
            }
            _ => ResourceKind::Other,
        }
    }

    /// The size in bytes of a type as laid out in a block; `stride` is the
    /// `MatrixStride` of the member it is, for a matrix.
    fn size(&self, id: u32, stride: Option<u32>, depth: u32, budget: &mut u32) -> u32 {
        if depth > 16 || !spend(budget) {
            return 0;
        }
        match self.ty(id) {
            Some((OP_TYPE_INT | OP_TYPE_FLOAT, [width, ..])) => width / 8,
            Some((OP_TYPE_VECTOR, [component, count, ..])) => {
                count.saturating_mul(self.size(*component, None, depth + 1, budget))
            }
            Some((OP_TYPE_MATRIX, [column, columns, ..])) => columns.saturating_mul(
                stride.unwrap_or_else(|| self.size(*column, None, depth + 1, budget)),
            ),
            Some((OP_TYPE_ARRAY, [elem, len, ..])) => {
                let len = self.constants.get(len).copied().unwrap_or(1);
                let stride = self
                    .decorations
                    .get(&(id, DEC_ARRAY_STRIDE))
                    .copied()
                    .unwrap_or_else(|| self.size(*elem, None, depth + 1, budget));
                len.saturating_mul(stride)
            }
            Some((OP_TYPE_STRUCT, members)) => {
                let mut end = 0u32;
                for (i, m) in members.iter().enumerate() {
                    let i = i as u32;
                    let offset = self
                        .member_decorations
                        .get(&(id, i, DEC_OFFSET))
                        .copied()
                        .unwrap_or(0);
                    let stride = self
                        .member_decorations
                        .get(&(id, i, DEC_MATRIX_STRIDE))
                        .copied();
                    end = end.max(offset.saturating_add(self.size(*m, stride, depth + 1, budget)));
                }
                end
            }
            // Booleans and anything unknown: one word.
            _ => 4,
        }
    }

    /// How many locations an input variable of type `id` takes: one per scalar or
    /// vector (two for a 64-bit vector of three or four), one per matrix column,
    /// times an array's length.
    fn locations(&self, id: u32, depth: u32, budget: &mut u32) -> u32 {
        if depth > 16 || !spend(budget) {
            return 1;
        }
        match self.ty(id) {
            Some((OP_TYPE_VECTOR, [component, count, ..])) => {
                let wide = matches!(
                    self.ty(*component),
                    Some((OP_TYPE_FLOAT | OP_TYPE_INT, [64, ..]))
                );
                if wide && *count > 2 {
                    2
                } else {
                    1
                }
            }
            Some((OP_TYPE_MATRIX, [column, columns, ..])) => {
                columns.saturating_mul(self.locations(*column, depth + 1, budget))
            }
            Some((OP_TYPE_ARRAY, [elem, len, ..])) => self
                .constants
                .get(len)
                .copied()
                .unwrap_or(1)
                .saturating_mul(self.locations(*elem, depth + 1, budget)),
            _ => 1,
        }
    }

    /// The interface-matching type of type `id`.
    fn io_type(&self, id: u32, depth: u32, budget: &mut u32) -> IoType {
        if depth > 16 || !spend(budget) {
            return IoType::Unknown;
        }
        match self.ty(id) {
            Some((OP_TYPE_FLOAT, [width, ..])) => IoType::Scalar(0, *width),
            Some((OP_TYPE_INT, [width, signed, ..])) => {
                IoType::Scalar(if *signed == 1 { 1 } else { 2 }, *width)
            }
            Some((OP_TYPE_VECTOR, [component, count, ..])) => IoType::Vector(
                Box::new(self.io_type(*component, depth + 1, budget)),
                *count,
            ),
            Some((OP_TYPE_MATRIX, [column, columns, ..])) => {
                IoType::Matrix(Box::new(self.io_type(*column, depth + 1, budget)), *columns)
            }
            Some((OP_TYPE_ARRAY, [elem, len, ..])) => IoType::Array(
                Box::new(self.io_type(*elem, depth + 1, budget)),
                self.constants.get(len).copied().unwrap_or(0),
            ),
            Some((OP_TYPE_STRUCT, members)) => IoType::Struct(
                members
                    .iter()
                    .map(|m| self.io_type(*m, depth + 1, budget))
                    .collect(),
            ),
            _ => IoType::Unknown,
        }
    }

    /// The user-defined inputs or outputs variable `id` of type `pointee` gives an
    /// entry point of execution model `model`, or its built-in block's members
    /// (`Err`), or nothing for a variable decorated `BuiltIn`.
    fn io(
        &self,
        id: u32,
        pointee: u32,
        output: bool,
        model: u32,
    ) -> std::result::Result<Vec<IoVar>, Vec<(u32, u32)>> {
        const BUILT_IN: u32 = 11;
        const PATCH: u32 = 15;
        const LOCATION: u32 = 30;
        const COMPONENT: u32 = 31;
        if self.decorations.contains_key(&(id, BUILT_IN)) {
            return Ok(Vec::new());
        }
        let patch = self.flags.contains(&(id, PATCH));
        // Tessellation control inputs and outputs, tessellation evaluation and
        // geometry inputs are arrays of one element per vertex, but for patch ones.
        let per_vertex = !patch
            && match model {
                1 => true,
                2 | 3 => !output,
                _ => false,
            };
        let ty = match (per_vertex, self.ty(pointee)) {
            (false, _) => pointee,
            (true, Some((OP_TYPE_ARRAY | OP_TYPE_RUNTIME_ARRAY, [elem, ..]))) => *elem,
            (true, _) => {
                return Ok(vec![IoVar {
                    output,
                    location: u32::MAX,
                    component: 0,
                    patch,
                    ty: IoType::Unknown,
                }])
            }
        };
        let location = self.decorations.get(&(id, LOCATION)).copied();
        let component = self.decorations.get(&(id, COMPONENT)).copied().unwrap_or(0);
        match self.ty(ty) {
            Some((OP_TYPE_STRUCT, members)) if self.flags.contains(&(ty, DEC_BLOCK)) => {
                let builtins: Vec<(u32, u32)> = self.builtins(0, pointee);
                if !builtins.is_empty() {
                    return Err(builtins);
                }
                let mut next = location.unwrap_or(u32::MAX);
                let mut out = Vec::new();
                for (i, member) in members.iter().enumerate() {
                    let i = i as u32;
                    let at = self.member_decorations.get(&(ty, i, LOCATION)).copied();
                    let location = at.unwrap_or(next);
                    let member_ty = self.io_type(*member, 0, &mut { TYPE_WALK });
                    next = match location {
                        u32::MAX => u32::MAX,
                        l => l.saturating_add(member_ty.locations()),
                    };
                    out.push(IoVar {
                        output,
                        location,
                        component: self
                            .member_decorations
                            .get(&(ty, i, COMPONENT))
                            .copied()
                            .unwrap_or(0),
                        patch: patch || self.member_flags.contains(&(ty, i, PATCH)),
                        ty: member_ty,
                    });
                }
                Ok(out)
            }
            _ => Ok(vec![IoVar {
                output,
                location: location.unwrap_or(u32::MAX),
                component,
                patch,
                ty: self.io_type(ty, 0, &mut { TYPE_WALK }),
            }]),
        }
    }

    /// The built-ins variable `id` of type `pointee` carries, each with its array
    /// size: its own `BuiltIn` decoration, or those of the members of the block it
    /// is (under any per-vertex arrays).
    fn builtins(&self, id: u32, pointee: u32) -> Vec<(u32, u32)> {
        const BUILT_IN: u32 = 11;
        let len = |t: u32| match self.ty(t) {
            Some((OP_TYPE_ARRAY, [_, len, ..])) => self.constants.get(len).copied().unwrap_or(0),
            _ => 1,
        };
        if let Some(builtin) = self.decorations.get(&(id, BUILT_IN)) {
            return vec![(*builtin, len(pointee))];
        }
        let (block, _) = self.element(pointee);
        let Some((OP_TYPE_STRUCT, members)) = self.ty(block) else {
            return Vec::new();
        };
        members
            .iter()
            .enumerate()
            .filter_map(|(i, member)| {
                let builtin = self.member_decorations.get(&(block, i as u32, BUILT_IN))?;
                Some((*builtin, len(*member)))
            })
            .collect()
    }

    /// The image type of a variable whose type under any arrays is `element`.
    fn image_shape(&self, element: u32) -> Option<ImageShape> {
        let image = match self.ty(element)? {
            (OP_TYPE_SAMPLED_IMAGE, [image, ..]) => *image,
            (OP_TYPE_IMAGE, _) => element,
            _ => return None,
        };
        // Operands: sampled type, Dim, Depth, Arrayed, MS, Sampled, format.
        let Some((OP_TYPE_IMAGE, [sampled, dim, _, arrayed, _, _, format, ..])) = self.ty(image)
        else {
            return None;
        };
        let numeric = match self.ty(*sampled) {
            Some((OP_TYPE_FLOAT, _)) => 1,
            Some((OP_TYPE_INT, _)) => 2,
            _ => 0,
        };
        Some(ImageShape {
            dim: *dim,
            arrayed: *arrayed == 1,
            numeric,
            format: *format,
        })
    }

    /// The bytes a push-constant block of struct type `id` spans.
    fn block_range(&self, id: u32) -> (u32, u32) {
        let Some((OP_TYPE_STRUCT, members)) = self.ty(id) else {
            return (0, self.size(id, None, 0, &mut { TYPE_WALK }));
        };
        let mut start = u32::MAX;
        for i in 0..members.len() as u32 {
            let offset = self
                .member_decorations
                .get(&(id, i, DEC_OFFSET))
                .copied()
                .unwrap_or(0);
            start = start.min(offset);
        }
        (
            start.min(self.size(id, None, 0, &mut { TYPE_WALK })),
            self.size(id, None, 0, &mut { TYPE_WALK }),
        )
    }
}

/// The instructions of a module after its five-word header: each opcode with its
/// words, the first (which holds the opcode and the word count) included. A
/// malformed instruction ends the walk.
/// How many types one walk of a type tree may visit. A module's types form a graph,
/// which a malformed one may give cycles and exponential fan-out (a structure of
/// sixteen copies of itself); a real shader's types are a few dozen.
const TYPE_WALK: u32 = 4096;

/// Takes one visit off `budget`; false when none is left.
fn spend(budget: &mut u32) -> bool {
    *budget = budget.saturating_sub(1);
    *budget > 0
}

fn instructions(words: &[u32]) -> impl Iterator<Item = (u32, &[u32])> {
    let mut at = 5;
    std::iter::from_fn(move || {
        let first = *words.get(at)?;
        let (count, op) = ((first >> 16) as usize, first & 0xffff);
        if count == 0 || at + count > words.len() {
            return None;
        }
        let w = &words[at..at + count];
        at += count;
        Some((op, w))
    })
}

/// The interface of the SPIR-V module in `words` (in the host's byte order, as
/// [`spirv_words`] returns them). Malformed instructions end the walk; what was read
/// until then is kept.
pub(crate) fn interface(words: &[u32]) -> Interface {
    const OP_CONSTANT: u32 = 43;
    const OP_DECORATE: u32 = 71;
    const OP_MEMBER_DECORATE: u32 = 72;
    const OP_VARIABLE: u32 = 59;
    const OP_ENTRY_POINT: u32 = 15;
    const OP_EXECUTION_MODE: u32 = 16;
    const OP_CAPABILITY: u32 = 17;
    const OP_SPEC_CONSTANT_TRUE: u32 = 48;
    const OP_SPEC_CONSTANT: u32 = 50;
    const SPEC_ID: u32 = 1;
    const EXECUTION_MODEL_VERTEX: u32 = 0;
    const INPUT: u32 = 1;
    const OUTPUT: u32 = 3;
    const LOCATION: u32 = 30;
    const BINDING: u32 = 33;
    const DESCRIPTOR_SET: u32 = 34;
    const INPUT_ATTACHMENT_INDEX: u32 = 43;
    const PUSH_CONSTANT: u32 = 9;
    let mut m = Module::default();
    let mut variables: Vec<(u32, u32, u32)> = Vec::new();
    // Each vertex entry point's name and interface ids.
    let mut vertex_entries: Vec<(String, Vec<u32>)> = Vec::new();
    // Every entry point's name and execution model.
    let mut entry_points: Vec<(u32, EntryPoint)> = Vec::new();
    // Execution modes by entry point id.
    let mut modes: Vec<(u32, u32, Vec<u32>)> = Vec::new();
    // Scalar specialization constants: opcode, result type and result id.
    let mut spec: Vec<(u32, u32, u32)> = Vec::new();
    // Each entry point's interface ids.
    let mut interfaces: Vec<(u32, Vec<u32>)> = Vec::new();
    let mut capabilities: Vec<u32> = Vec::new();
    for (op, w) in instructions(words) {
        match (op, w.len()) {
            (OP_DECORATE, 3) => {
                m.flags.insert((w[1], w[2]));
            }
            (OP_DECORATE, 4..) => {
                m.decorations.insert((w[1], w[2]), w[3]);
            }
            (OP_MEMBER_DECORATE, 4) => {
                m.member_flags.insert((w[1], w[2], w[3]));
            }
            (OP_MEMBER_DECORATE, 5..) => {
                m.member_decorations.insert((w[1], w[2], w[3]), w[4]);
            }
            (OP_TYPE_INT..=OP_TYPE_POINTER, 2..) => {
                m.types.insert(w[1], (op, w[2..].to_vec()));
            }
            (OP_CONSTANT, 4..) => {
                m.constants.insert(w[2], w[3]);
            }
            (OP_VARIABLE, 4..) => variables.push((w[1], w[2], w[3])),
            (OP_EXECUTION_MODE, 3..) => modes.push((w[1], w[2], w[3..].to_vec())),
            (OP_CAPABILITY, 2..) => capabilities.push(w[1]),
            (OP_SPEC_CONSTANT_TRUE..=OP_SPEC_CONSTANT, 3..) => spec.push((op, w[1], w[2])),
            (OP_ENTRY_POINT, 4..) => {
                // The name is a nul-terminated string packed four bytes a word; the
                // interface ids follow it.
                let mut name = Vec::new();
                let mut rest = &w[3..];
                while let Some((word, tail)) = rest.split_first() {
                    rest = tail;
                    let bytes = word.to_le_bytes();
                    let end = bytes.iter().position(|b| *b == 0);
                    name.extend_from_slice(&bytes[..end.unwrap_or(4)]);
                    if end.is_some() {
                        break;
                    }
                }
                let name = String::from_utf8_lossy(&name).into_owned();
                entry_points.push((
                    w[2],
                    EntryPoint {
                        name: name.clone(),
                        model: w[1],
                        ..EntryPoint::default()
                    },
                ));
                interfaces.push((w[2], rest.to_vec()));
                if w[1] == EXECUTION_MODEL_VERTEX {
                    vertex_entries.push((name, rest.to_vec()));
                }
            }
            _ => {}
        }
    }
    let (used, unplaced) = variable_ops(words, &variables);
    let stored = stored_builtins(words, &m, &variables);
    for (entry, ids) in interfaces {
        let writes: Vec<u32> = stored
            .iter()
            .filter(|(var, _)| ids.contains(var))
            .map(|(_, b)| *b)
            .collect();
        if let Some((_, e)) = entry_points.iter_mut().find(|(e, _)| *e == entry) {
            e.writes = writes;
        }
        let builtins: Vec<(u32, u32, u32)> = variables
            .iter()
            .filter(|(_, id, _)| ids.contains(id))
            .flat_map(|(ty, id, storage)| {
                let pointee = match m.ty(*ty) {
                    Some((OP_TYPE_POINTER, [_, pointee, ..])) => *pointee,
                    _ => 0,
                };
                m.builtins(*id, pointee)
                    .into_iter()
                    .map(move |(builtin, len)| (builtin, *storage, len))
            })
            .collect();
        if let Some((_, e)) = entry_points.iter_mut().find(|(e, _)| *e == entry) {
            e.builtins = builtins;
            for (ty, id, storage) in variables.iter().filter(|(_, id, _)| ids.contains(id)) {
                let output = match *storage {
                    INPUT => false,
                    OUTPUT => true,
                    _ => continue,
                };
                let pointee = match m.ty(*ty) {
                    Some((OP_TYPE_POINTER, [_, pointee, ..])) => *pointee,
                    _ => 0,
                };
                match m.io(*id, pointee, output, e.model) {
                    Ok(io) => e.io.extend(io),
                    Err(block) => e.builtin_blocks[usize::from(output)] = block,
                }
            }
        }
    }
    for (id, mode, operands) in modes {
        if let Some((_, e)) = entry_points.iter_mut().find(|(e, _)| *e == id) {
            e.modes.push((mode, operands));
        }
    }
    let spec_constants = spec
        .into_iter()
        .filter_map(|(op, ty, id)| {
            let spec_id = *m.decorations.get(&(id, SPEC_ID))?;
            let size = match (op, m.ty(ty)) {
                (OP_SPEC_CONSTANT, Some((OP_TYPE_INT | OP_TYPE_FLOAT, [width, ..]))) => width / 8,
                (OP_SPEC_CONSTANT, _) => return None,
                // OpSpecConstantTrue and OpSpecConstantFalse: a boolean.
                _ => 4,
            };
            Some((spec_id, size))
        })
        .collect();
    let mut out = Interface {
        entry_points: entry_points.into_iter().map(|(_, e)| e).collect(),
        spec_constants,
        capabilities,
        ..Interface::default()
    };
    for (name, ids) in vertex_entries {
        let inputs = variables
            .iter()
            .filter(|(_, id, storage)| *storage == INPUT && ids.contains(id))
            .filter_map(|(ty, id, _)| {
                let location = m.decorations.get(&(*id, LOCATION))?;
                let pointee = match m.ty(*ty) {
                    Some((OP_TYPE_POINTER, [_, pointee, ..])) => *pointee,
                    _ => return None,
                };
                Some((*location, m.locations(pointee, 0, &mut { TYPE_WALK })))
            })
            .collect();
        out.vertex_inputs.push((name, inputs));
    }
    for (ty, id, storage) in variables {
        let pointee = match m.ty(ty) {
            Some((OP_TYPE_POINTER, [_, pointee, ..])) => *pointee,
            _ => continue,
        };
        if storage == PUSH_CONSTANT {
            let (start, end) = m.block_range(pointee);
            out.push_constants = Some(match out.push_constants {
                Some((s, e)) => (s.min(start), e.max(end)),
                None => (start, end),
            });
            continue;
        }
        let (Some(&set), Some(&binding)) = (
            m.decorations.get(&(id, DESCRIPTOR_SET)),
            m.decorations.get(&(id, BINDING)),
        ) else {
            continue;
        };
        let (element, count) = m.element(pointee);
        let (ops, write_components) = used.get(&id).copied().unwrap_or((0, 0));
        let image = m.image_shape(element);
        // Loading an image variable loads a handle, not its memory.
        let handle = image.map_or(0, |_| ops::LOAD | ops::STORE);
        let ops = ops & !handle;
        out.resources.push(Resource {
            set,
            binding,
            kind: m.kind(storage, element),
            count,
            image,
            ops,
            write_components,
            input_index: m.decorations.get(&(id, INPUT_ATTACHMENT_INDEX)).copied(),
        });
    }
    // An operation whose variable was not found may be on any image variable.
    for r in out.resources.iter_mut().filter(|r| r.image.is_some()) {
        r.ops |= unplaced.0;
        r.write_components = fewest(r.write_components, unplaced.1);
    }
    out
}

/// The fewer of two texel component counts, 0 standing for none written.
fn fewest(a: u8, b: u8) -> u8 {
    match (a, b) {
        (0, n) | (n, 0) => n,
        (a, b) => a.min(b),
    }
}

/// The (variable, built-in) pairs an `OpStore` of the module writes: a store to a
/// variable decorated `BuiltIn`, or through an access chain into a member of a block
/// variable (under one level of per-vertex array) that is.
fn stored_builtins(words: &[u32], m: &Module, variables: &[(u32, u32, u32)]) -> Vec<(u32, u32)> {
    const OP_STORE: u32 = 62;
    const OP_ACCESS_CHAIN: u32 = 65;
    const OP_IN_BOUNDS_ACCESS_CHAIN: u32 = 66;
    const BUILT_IN: u32 = 11;
    // Each access chain's base and indices, and the pointers stored to.
    let mut chains: HashMap<u32, (u32, Vec<u32>)> = HashMap::new();
    let mut stores: Vec<u32> = Vec::new();
    for (op, w) in instructions(words) {
        match (op, &w[1..]) {
            (OP_ACCESS_CHAIN | OP_IN_BOUNDS_ACCESS_CHAIN, [_, id, base, indices @ ..]) => {
                chains.insert(*id, (*base, indices.to_vec()));
            }
            (OP_STORE, [pointer, ..]) => stores.push(*pointer),
            _ => {}
        }
    }
    let mut out = Vec::new();
    for pointer in stores {
        // The chain from a variable down to the pointer, its indices in order.
        let (mut root, mut indices) = (pointer, Vec::new());
        for _ in 0..8 {
            let Some((base, more)) = chains.get(&root) else {
                break;
            };
            indices.splice(0..0, more.iter().copied());
            root = *base;
        }
        let Some((ty, _, _)) = variables.iter().find(|(_, id, _)| *id == root) else {
            continue;
        };
        if let Some(b) = m.decorations.get(&(root, BUILT_IN)) {
            out.push((root, *b));
            continue;
        }
        let Some((OP_TYPE_POINTER, [_, pointee, ..])) = m.ty(*ty) else {
            continue;
        };
        // A block, or an array of blocks (per vertex) whose first index is the vertex.
        let (block, member_at) = match m.ty(*pointee) {
            Some((OP_TYPE_ARRAY | OP_TYPE_RUNTIME_ARRAY, [elem, ..])) => (*elem, 1),
            _ => (*pointee, 0),
        };
        let member = indices.get(member_at).and_then(|i| m.constants.get(i));
        if let Some(b) = member.and_then(|i| m.member_decorations.get(&(block, *i, BUILT_IN))) {
            out.push((root, *b));
        }
    }
    out.sort_unstable();
    out.dedup();
    out
}

/// What a module's instructions do with one variable: [`ops`] bits, and the fewest
/// components of a texel `OpImageWrite` writes through it (0: none).
type Uses = (u16, u8);

/// The [`Uses`] each variable of `variables` takes from the module's instructions
/// (by variable id), and those on values of no variable found.
fn variable_ops(words: &[u32], variables: &[(u32, u32, u32)]) -> (HashMap<u32, Uses>, Uses) {
    const OP_FUNCTION: u32 = 54;
    const OP_FUNCTION_PARAMETER: u32 = 55;
    const OP_FUNCTION_CALL: u32 = 57;
    const OP_IMAGE_TEXEL_POINTER: u32 = 60;
    const OP_LOAD: u32 = 61;
    const OP_ACCESS_CHAIN: u32 = 65;
    const OP_PTR_ACCESS_CHAIN: u32 = 67;
    const OP_COPY_OBJECT: u32 = 83;
    const OP_SAMPLED_IMAGE: u32 = 86;
    const OP_IMAGE_READ: u32 = 98;
    const OP_IMAGE_WRITE: u32 = 99;
    const OP_IMAGE: u32 = 100;
    const OP_SELECT: u32 = 169;
    const OP_PHI: u32 = 245;
    const OP_IMAGE_SPARSE_READ: u32 = 320;
    // Sampling, fetch and gather instructions: (opcode, with depth comparison).
    let sample = |op: u32| match op {
        87 | 88 | 91 | 92 | 95 | 96 | 305 | 306 | 309 | 310 | 313 | 314 => Some(false),
        89 | 90 | 93 | 94 | 97 | 307 | 308 | 311 | 312 | 315 => Some(true),
        _ => None,
    };
    // Where each image instruction's image operands mask is (an index into the
    // operands after the opcode), and whether it is an `OpImageSample*` or
    // `OpImageSparseSample*` instruction.
    let operands_at = |op: u32| match op {
        87 | 88 | 91 | 92 | 305 | 306 | 309 | 310 => Some((4, true)),
        89 | 90 | 93 | 94 | 307 | 308 | 311 | 312 => Some((5, true)),
        95 | 98 | 313 | 320 => Some((4, false)),
        96 | 97 | 314 | 315 => Some((5, false)),
        OP_IMAGE_WRITE => Some((3, false)),
        _ => None,
    };
    // Image operands: Bias, ConstOffset, Offset, ConstOffsets.
    const BIAS: u32 = 0x1;
    const OFFSETS: u32 = 0x8 | 0x10 | 0x20;
    const OP_IMAGE_QUERY_SIZE_LOD: u32 = 103;
    const OP_IMAGE_QUERY_SAMPLES: u32 = 107;
    // Each instruction (opcode and operands), and the parameters of each function.
    let mut code: Vec<(u32, &[u32])> = Vec::new();
    let mut params: HashMap<u32, Vec<u32>> = HashMap::new();
    let mut function = 0;
    for (op, w) in instructions(words) {
        let w = &w[1..];
        match (op, w) {
            (OP_FUNCTION, [_, id, ..]) => function = *id,
            (OP_FUNCTION_PARAMETER, [_, id, ..]) => params.entry(function).or_default().push(*id),
            _ => {}
        }
        code.push((op, w));
    }
    // The variables each id derives from, to a fixed point (a phi or a call may
    // name a value defined further on).
    let mut origin: HashMap<u32, Vec<u32>> = variables
        .iter()
        .map(|(_, id, _)| (*id, vec![*id]))
        .collect();
    let flow = |origin: &mut HashMap<u32, Vec<u32>>, to: u32, from: &[u32]| -> bool {
        let mut found: Vec<u32> = from
            .iter()
            .filter_map(|f| origin.get(f))
            .flatten()
            .copied()
            .collect();
        if found.is_empty() {
            return false;
        }
        let entry = origin.entry(to).or_default();
        let before = entry.len();
        entry.append(&mut found);
        entry.sort_unstable();
        entry.dedup();
        entry.len() != before
    };
    // Each pass only adds (id, variable) pairs, of which there are finitely many.
    loop {
        let mut changed = false;
        for &(op, w) in &code {
            changed |= match (op, w) {
                (OP_LOAD | OP_COPY_OBJECT | OP_IMAGE, [_, id, from, ..]) => {
                    flow(&mut origin, *id, &[*from])
                }
                (OP_ACCESS_CHAIN..=OP_PTR_ACCESS_CHAIN, [_, id, base, ..]) => {
                    flow(&mut origin, *id, &[*base])
                }
                (OP_SAMPLED_IMAGE, [_, id, image, sampler, ..]) => {
                    flow(&mut origin, *id, &[*image, *sampler])
                }
                (OP_SELECT, [_, id, _, a, b, ..]) => flow(&mut origin, *id, &[*a, *b]),
                (OP_PHI, [_, id, pairs @ ..]) => {
                    let values: Vec<u32> = pairs.iter().step_by(2).copied().collect();
                    flow(&mut origin, *id, &values)
                }
                (OP_FUNCTION_CALL, [_, _, callee, args @ ..]) => {
                    let mut changed = false;
                    for (param, arg) in params.get(callee).into_iter().flatten().zip(args) {
                        changed |= flow(&mut origin, *param, &[*arg]);
                    }
                    changed
                }
                _ => false,
            };
        }
        if !changed {
            break;
        }
    }
    // The type of each value that a texel written with `OpImageWrite` can be:
    // instructions with a result type and a result, the result type first.
    let typed = |op: u32| matches!(op, 41..=52 | 54 | 55 | 57 | 59..=61 | 65..=70 | 77..=98 | 100..=217 | 229..=245);
    let type_of: HashMap<u32, u32> = code
        .iter()
        .filter(|(op, _)| typed(*op))
        .filter_map(|(_, w)| Some((*w.get(1)?, *w.first()?)))
        .collect();
    let mut types: HashMap<u32, (u32, u32)> = HashMap::new();
    for &(op, w) in &code {
        if let (OP_TYPE_VECTOR, [id, _, count, ..]) = (op, w) {
            types.insert(*id, (op, *count));
        }
    }
    // A texel's components: a vector's count, or one for a scalar.
    let components = |texel: u32| -> u8 {
        let count = type_of
            .get(&texel)
            .and_then(|ty| types.get(ty))
            .map_or(1, |(_, n)| *n);
        u8::try_from(count).unwrap_or(u8::MAX)
    };
    let mut used: HashMap<u32, Uses> = HashMap::new();
    let mut unplaced: Uses = (0, 0);
    // Loads and stores: only those traced to a variable (most are a function's own).
    // OpStore, OpAtomicStore; OpAtomicLoad; OpCopyMemory(Sized); the other atomics.
    let atomic = |op: u32| matches!(op, 229..=242 | 318 | 5614 | 5615 | 6035);
    for &(op, w) in &code {
        let (pointer, bits) = match (op, w) {
            (OP_LOAD | 227, [_, _, pointer, ..]) => (*pointer, ops::LOAD),
            (62 | 228, [pointer, ..]) => (*pointer, ops::STORE),
            (63 | 64, [target, source, ..]) => {
                for v in origin.get(source).into_iter().flatten() {
                    used.entry(*v).or_default().0 |= ops::LOAD;
                }
                (*target, ops::STORE)
            }
            (op, [_, _, pointer, ..]) if atomic(op) => (*pointer, ops::LOAD | ops::STORE),
            _ => continue,
        };
        for v in origin.get(&pointer).into_iter().flatten() {
            used.entry(*v).or_default().0 |= bits;
        }
    }
    let mut mark = |id: u32, bits: u16, written: u8| {
        let add = |u: &mut Uses| {
            u.0 |= bits;
            u.1 = fewest(u.1, written);
        };
        match origin.get(&id) {
            Some(vars) => {
                for v in vars {
                    add(used.entry(*v).or_default());
                }
            }
            None => add(&mut unplaced),
        }
    };
    for &(op, w) in &code {
        // The operands mask of an image instruction, where it has one.
        let operands =
            operands_at(op).map(|(at, sampling)| (w.get(at).copied().unwrap_or(0), sampling));
        let offsets = match operands {
            Some((mask, sampling)) => {
                let mut bits = 0;
                if mask & OFFSETS != 0 {
                    bits |= ops::OFFSET;
                }
                if sampling && mask & (BIAS | OFFSETS) != 0 {
                    bits |= ops::SAMPLE_BIAS_OFFSET;
                }
                bits
            }
            None => 0,
        };
        match (op, w) {
            (OP_IMAGE_TEXEL_POINTER, [_, _, image, ..]) => {
                mark(*image, ops::ATOMIC | ops::NOT_SAMPLE, 0)
            }
            (OP_IMAGE_READ | OP_IMAGE_SPARSE_READ, [_, _, image, ..]) => {
                mark(*image, ops::READ | ops::NOT_SAMPLE | offsets, 0)
            }
            (OP_IMAGE_WRITE, [image, _, texel, ..]) => mark(
                *image,
                ops::WRITE | ops::NOT_SAMPLE | offsets,
                components(*texel),
            ),
            (OP_IMAGE_QUERY_SIZE_LOD..=OP_IMAGE_QUERY_SAMPLES, [_, _, image, ..]) => {
                mark(*image, ops::NOT_SAMPLE, 0)
            }
            (op, [_, _, image, ..]) => {
                if let Some(dref) = sample(op) {
                    let mut bits = ops::SAMPLE | offsets;
                    if dref {
                        bits |= ops::DREF;
                    }
                    match operands_at(op) {
                        Some((_, true)) => {
                            let implicit = matches!(op, 87 | 89 | 91 | 93 | 305 | 307 | 309 | 311);
                            let proj = matches!(op, 91..=94 | 309..=312);
                            if implicit || proj || dref {
                                bits |= ops::IMPLICIT_DREF_PROJ;
                            }
                        }
                        _ => bits |= ops::NOT_SAMPLE,
                    }
                    mark(*image, bits, 0);
                }
            }
            _ => {}
        }
    }
    (used, unplaced)
}

#[cfg(test)]
mod tests;
