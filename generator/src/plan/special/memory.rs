//! The special-case rows of one concern; their functions are the `tuff` crate's
//! `special/memory.rs`, and a row here calls no other (but the image-layout tracker).
//!
//! Device memory: allocation (counts, types, dedicated and exported memory), the
//! binding of buffers and images to it, and the memory requirements it is checked against.

use super::{call, How, Keeps, Special, NONE, UNPROVEN};

const DEVICE_INDICES: &str = "checks a chained device group info's device indices against the device's physical-device count, recorded at its creation";
const UNPROVEN_INSTANCES: &str = "checked by the safe methods in every build (a chained device group info with device indices is refused on a device of more than one physical device, whose memory instances tuff does not follow; on one physical device its only instance exists), but no test breaks it: lavapipe's devices have one physical device";
const MEMORY_KIND: &str = "checks what the allocation asked for (its dedicated object, exportable handle types and device address, kept from its allocation) against the object the bind gives it to";
const UNPROVEN_DEDICATED: &str = "checked by the safe methods in every build (VkMemoryDedicatedRequirements, queried at the bind, against the allocation's dedicated object), but no test breaks it: lavapipe requires no dedicated allocation";
const UNPROVEN_PROTECTED: &str = "checked by the safe methods in every build (the object's protected flag against its memory's type), but no test breaks it: lavapipe has no protected memory";
const NO_IMPORT: &str = "memory is imported only through structs of extensions tuff does not emit (VK_KHR_external_memory_fd and the like), which no safe allocate info can chain";
const LAZY: &str = "checks the memory's type, kept from its allocation, is lazily allocated";
const PLANES: &str = "checks a chained plane info against the image's create flags and format, kept from its creation";
const UNPROVEN_DISJOINT: &str = "checked by the safe methods in every build (the image's create flags are kept from its creation), but no test breaks it yet: lavapipe has no format that supports disjoint planes";
const DEVICE_MASK: &str = "checks the mask is not zero and names only the physical devices the device was created with (a chained device group create info's count, recorded at creation)";
const UNPROVEN_ALLOCATION_COUNT: &str = "checked by the safe methods in every build (the live allocations the device lists against maxMemoryAllocationCount, under a lock held until the new memory is listed), but no test breaks it: lavapipe allows 4,294,967,295 allocations";
const UNPROVEN_PROTECTED_TYPE: &str = "checked by the safe methods in every build (the memory type's flags against protectedMemory), but no test breaks it: lavapipe has no protected memory type";
const UNPROVEN_SPARSE_DEDICATED: &str = "checked by the safe methods in every build (the object's recorded creation flags), but no test breaks it: lavapipe 22.3 has no sparseBinding, so no sparse object can be named";
const UNPROVEN_DISJOINT_DEDICATED: &str = "checked by the safe methods in every build (the image's recorded creation flags), but no test breaks it: the tests make no disjoint image";
const DEDICATED: &str = "checks the dedicated image or buffer against its recorded creation flags (not sparse, not disjoint), one of the two named, and the allocation size against its memory requirements";
const EXPORT: &str = "checks the exported handle types against the external memory properties the physical device reports for the dedicated image or buffer (exportable, compatible with each other); an export without a dedicated object is refused (`Error::Misuse`)";
const MEMORY_TYPES: &str = "checks the memory type index and the size against the physical device's memory types and heaps, a protected type against protectedMemory, and the chained allocation flags and capture address against the device's bufferDeviceAddress features";
const BIND_BOUND: &str = "refuses an object the device recorded as bound (and one an earlier info of the same call binds)";
const BIND_MEMORY: &str = "checks the memory's recorded size and type against the object's memory requirements, read from the driver at the bind";
const BIND_TWICE: &str = "refuses an image an earlier info of the same call binds";
const IMAGE_GROUP: &str = "checks a chained VkBindImageMemoryDeviceGroupInfo's device indices and split instance bind region count against the device's physical-device count, recorded at its creation, and split regions against the image's create flags";
const IMAGE_GROUP_ALONE: &str = "checks each device index of a chained VkBindImageMemoryDeviceGroupInfo against the device's physical-device count, recorded at its creation (the 1.3.239 layer does not check it: the error alone proves it)";
const IMAGE_GROUP_SPLIT: &str = "checks a chained VkBindImageMemoryDeviceGroupInfo's counts against each other and the device's physical-device count (the 1.3.239 layer names VUID-VkBindImageMemoryInfo-pNext-01627 first, which every split region on lavapipe breaks as well, its images being made without split instance bind regions: the error alone proves it)";
const UNPROVEN_IMAGE_INSTANCES: &str = "checked by the safe methods in every build (a chained device group info with device indices is refused on a device of more than one physical device, whose memory instances tuff does not follow), but no test breaks it: lavapipe's devices have one physical device";
const SPLIT_REFUSED: &str = "checked by the safe methods in every build: the safe `bind_image_memory2` refuses split instance bind regions (`Error::Misuse`: tuff does not follow the memory instances of a device group), so no bind made through it names one";
const DISJOINT_REFUSED: &str = "checked by the safe methods in every build: the safe `bind_image_memory2` refuses the planes of a disjoint image (`Error::Misuse`: the device records one binding per image, which the overlap checks of copies, blits and attachments read), so no bind made through it binds a plane";
const UNPROVEN_SWAPCHAIN_BIND: &str = "checked by the safe methods in every build (a chained VkBindImageMemorySwapchainInfoKHR is refused, as its memory must be VK_NULL_HANDLE and the safe info always names memory, and so is an image created with a VkImageSwapchainCreateInfoKHR, recorded at its creation), but no test breaks it yet: it needs a swapchain";
const WHOLE: &str = "`DeviceMemory::map` maps the whole memory: offset 0, size VK_WHOLE_SIZE";

const PEER_INDICES: &str = "checks the heap index against the physical device's memory heaps, and both device indices against the physical devices the device was created with (recorded at its creation), which must differ (the 1.3.239 layer does not check them: the error alone proves them)";
const CAPTURE_MEMORY: &str = "checks the memory's allocation flags, kept from its allocation, include VK_MEMORY_ALLOCATE_DEVICE_ADDRESS_BIT";
const UNPROVEN_CAPTURE_MULTI_DEVICE: &str = "checked by the safe methods in every build (the device's physical-device count and features, recorded at its creation), but no test breaks it: lavapipe's devices are not device groups";

const DEVICE_IMAGE_PLANES: &str = "checks the create info's chain, and a disjoint image's plane aspect against its format's planes (the 1.3.239 layer does not check them: the error alone proves them)";

/// The rows of `vkGetDeviceImageMemoryRequirements` and its sparse twin, which take
/// the same info: both check its rules, the first row settles them.
macro_rules! device_image_requirements {
    ($command:literal, $settles:expr) => {
        Special {
            command: $command,
            check: call(
                "special::memory::device_image_requirements_checks",
                &["self", "info"],
            ),
            settles: $settles,
            ..NONE
        }
    };
}

const MAPPED_RANGE: &str = "checks, under the lock of the device's memory records that mapping and unmapping take, that a MappedMemory of the memory lives (it maps the whole memory), and the range against the memory's size and nonCoherentAtomSize";
const MAPPED_PAST_END: &str = "checks, as for the other rules of the range, that an offset with VK_WHOLE_SIZE lies before the memory's end, where the mapping ends (the 1.3.239 layer checks only an offset below the mapping's start, which a mapping of the whole memory cannot have: the error alone proves it)";
const MAPPED_WHOLE: &str =
    "`DeviceMemory::map` maps the whole memory, so the mapping ends where the memory does";

/// The rows of `vkFlushMappedMemoryRanges` and `vkInvalidateMappedMemoryRanges`, whose
/// rules are their struct's: both check them, the first row settles them.
macro_rules! mapped_ranges {
    ($command:literal, $settles:expr) => {
        Special {
            command: $command,
            hold: call(
                "special::memory::mapped_ranges_hold",
                &["self", "memory_ranges"],
            ),
            settles: $settles,
            ..NONE
        }
    };
}

/// The rows of this concern.
pub(super) const ROWS: &[Special] = &[
    mapped_ranges!(
        "vkFlushMappedMemoryRanges",
        &[
            (
                "VUID-VkMappedMemoryRange-memory-00684",
                How::Dynamic(MAPPED_RANGE)
            ),
            (
                "VUID-VkMappedMemoryRange-size-00685",
                How::Dynamic(MAPPED_RANGE)
            ),
            (
                "VUID-VkMappedMemoryRange-size-00686",
                How::Dynamic(MAPPED_PAST_END)
            ),
            (
                "VUID-VkMappedMemoryRange-offset-00687",
                How::Dynamic(MAPPED_RANGE)
            ),
            (
                "VUID-VkMappedMemoryRange-size-01389",
                How::Static(MAPPED_WHOLE)
            ),
            (
                "VUID-VkMappedMemoryRange-size-01390",
                How::Dynamic(MAPPED_RANGE)
            ),
        ]
    ),
    mapped_ranges!("vkInvalidateMappedMemoryRanges", &[]),
    device_image_requirements!(
        "vkGetDeviceImageMemoryRequirements",
        &[
            (
                "VUID-VkDeviceImageMemoryRequirementsKHR-pCreateInfo-06416",
                How::Dynamic(DEVICE_IMAGE_PLANES)
            ),
            (
                "VUID-VkDeviceImageMemoryRequirementsKHR-pCreateInfo-06417",
                How::Dynamic(DEVICE_IMAGE_PLANES)
            ),
            (
                "VUID-VkDeviceImageMemoryRequirementsKHR-pCreateInfo-06419",
                How::Dynamic(DEVICE_IMAGE_PLANES)
            ),
        ]
    ),
    device_image_requirements!("vkGetDeviceImageSparseMemoryRequirements", &[]),
    Special {
        command: "vkGetDeviceGroupPeerMemoryFeatures",
        check: call(
            "special::memory::peer_memory_checks",
            &[
                "self",
                "heap_index",
                "local_device_index",
                "remote_device_index",
            ],
        ),
        settles: &[
            (
                "VUID-vkGetDeviceGroupPeerMemoryFeatures-heapIndex-00691",
                How::Dynamic(PEER_INDICES),
            ),
            (
                "VUID-vkGetDeviceGroupPeerMemoryFeatures-localDeviceIndex-00692",
                How::Dynamic(PEER_INDICES),
            ),
            (
                "VUID-vkGetDeviceGroupPeerMemoryFeatures-remoteDeviceIndex-00693",
                How::Dynamic(PEER_INDICES),
            ),
            (
                "VUID-vkGetDeviceGroupPeerMemoryFeatures-localDeviceIndex-00694",
                How::Dynamic(PEER_INDICES),
            ),
        ],
        ..NONE
    },
    Special {
        command: "vkGetDeviceMemoryOpaqueCaptureAddress",
        check_last: call(
            "special::memory::memory_capture_address_checks",
            &["self", "info"],
        ),
        settles: &[
            (
                "VUID-vkGetDeviceMemoryOpaqueCaptureAddress-device-03335",
                How::User(UNPROVEN_CAPTURE_MULTI_DEVICE),
            ),
            (
                "VUID-VkDeviceMemoryOpaqueCaptureAddressInfo-memory-03336",
                How::Dynamic(CAPTURE_MEMORY),
            ),
        ],
        ..NONE
    },
    Special {
        command: "vkBindBufferMemory",
        check: call(
            "special::memory::bind_buffer_memory_checks",
            &["self", "buffer", "memory", "memory_offset"],
        ),
        after: call(
            "special::memory::bind_buffer_memory_done",
            &["self", "buffer", "memory", "memory_offset"],
        ),
        settles: &[
            (
                "VUID-vkBindBufferMemory-buffer-07459",
                How::Dynamic(BIND_BOUND),
            ),
            ("VUID-vkBindBufferMemory-buffer-01030", How::User(UNPROVEN)),
            (
                "VUID-vkBindBufferMemory-memoryOffset-01031",
                How::Dynamic(BIND_MEMORY),
            ),
            ("VUID-vkBindBufferMemory-memory-01035", How::User(UNPROVEN)),
            (
                "VUID-vkBindBufferMemory-memoryOffset-01036",
                How::Dynamic(BIND_MEMORY),
            ),
            (
                "VUID-vkBindBufferMemory-size-01037",
                How::Dynamic(BIND_MEMORY),
            ),
            (
                "VUID-vkBindBufferMemory-buffer-01444",
                How::User(UNPROVEN_DEDICATED),
            ),
            (
                "VUID-vkBindBufferMemory-memory-01508",
                How::Dynamic(MEMORY_KIND),
            ),
            (
                "VUID-vkBindBufferMemory-None-01898",
                How::User(UNPROVEN_PROTECTED),
            ),
            (
                "VUID-vkBindBufferMemory-None-01899",
                How::User(UNPROVEN_PROTECTED),
            ),
            (
                "VUID-vkBindBufferMemory-memory-02726",
                How::Dynamic(MEMORY_KIND),
            ),
            (
                "VUID-vkBindBufferMemory-memory-02727",
                How::Static(NO_IMPORT),
            ),
            (
                "VUID-vkBindBufferMemory-bufferDeviceAddress-03339",
                How::Dynamic(MEMORY_KIND),
            ),
        ],
        ..NONE
    },
    Special {
        command: "vkBindBufferMemory2",
        check: call(
            "special::memory::bind_buffer_memory2_checks",
            &["self", "bind_infos"],
        ),
        after: call(
            "special::memory::bind_buffer_memory2_done",
            &["self", "bind_infos"],
        ),
        settles: &[
            (
                "VUID-VkBindBufferMemoryInfo-buffer-07459",
                How::Dynamic(BIND_BOUND),
            ),
            (
                "VUID-VkBindBufferMemoryInfo-buffer-01030",
                How::User(UNPROVEN),
            ),
            (
                "VUID-VkBindBufferMemoryInfo-memoryOffset-01031",
                How::Dynamic(BIND_MEMORY),
            ),
            (
                "VUID-VkBindBufferMemoryInfo-memory-01035",
                How::User(UNPROVEN),
            ),
            (
                "VUID-VkBindBufferMemoryInfo-memoryOffset-01036",
                How::Dynamic(BIND_MEMORY),
            ),
            (
                "VUID-VkBindBufferMemoryInfo-size-01037",
                How::Dynamic(BIND_MEMORY),
            ),
            (
                "VUID-VkBindBufferMemoryInfo-buffer-01444",
                How::User(UNPROVEN_DEDICATED),
            ),
            (
                "VUID-VkBindBufferMemoryInfo-memory-01508",
                How::Dynamic(MEMORY_KIND),
            ),
            (
                "VUID-VkBindBufferMemoryInfo-None-01898",
                How::User(UNPROVEN_PROTECTED),
            ),
            (
                "VUID-VkBindBufferMemoryInfo-None-01899",
                How::User(UNPROVEN_PROTECTED),
            ),
            (
                "VUID-VkBindBufferMemoryInfo-memory-02726",
                How::Dynamic(MEMORY_KIND),
            ),
            (
                "VUID-VkBindBufferMemoryInfo-memory-02727",
                How::Static(NO_IMPORT),
            ),
            (
                "VUID-VkBindBufferMemoryInfo-bufferDeviceAddress-03339",
                How::Dynamic(MEMORY_KIND),
            ),
            (
                "VUID-VkBindBufferMemoryDeviceGroupInfo-deviceIndexCount-01606",
                How::Dynamic(DEVICE_INDICES),
            ),
            (
                "VUID-VkBindBufferMemoryDeviceGroupInfo-pDeviceIndices-01607",
                How::Dynamic(DEVICE_INDICES),
            ),
            (
                "VUID-VkBindBufferMemoryInfo-pNext-01605",
                How::User(UNPROVEN_INSTANCES),
            ),
        ],
        ..NONE
    },
    Special {
        command: "vkBindImageMemory2",
        check: call(
            "special::memory::bind_image_memory2_checks",
            &["self", "bind_infos"],
        ),
        after: call(
            "special::memory::bind_image_memory2_done",
            &["self", "bind_infos"],
        ),
        settles: &[
            (
                "VUID-VkBindImageMemoryInfo-image-07460",
                How::Dynamic(BIND_BOUND),
            ),
            (
                "VUID-VkBindImageMemoryInfo-image-01045",
                How::User(UNPROVEN),
            ),
            (
                "VUID-VkBindImageMemoryInfo-memoryOffset-01046",
                How::Dynamic(BIND_MEMORY),
            ),
            (
                "VUID-VkBindImageMemoryInfo-pNext-01615",
                How::User(UNPROVEN),
            ),
            (
                "VUID-VkBindImageMemoryInfo-pNext-01616",
                How::Dynamic(BIND_MEMORY),
            ),
            (
                "VUID-VkBindImageMemoryInfo-pNext-01617",
                How::Dynamic(BIND_MEMORY),
            ),
            (
                "VUID-VkBindImageMemoryInfo-pNext-01618",
                How::User(UNPROVEN),
            ),
            (
                "VUID-vkBindImageMemory2-pBindInfos-04006",
                How::Dynamic(BIND_TWICE),
            ),
            (
                "VUID-VkBindImageMemoryInfo-image-01445",
                How::User(UNPROVEN_DEDICATED),
            ),
            (
                "VUID-VkBindImageMemoryInfo-memory-01509",
                How::Dynamic(MEMORY_KIND),
            ),
            (
                "VUID-VkBindImageMemoryInfo-None-01901",
                How::User(UNPROVEN_PROTECTED),
            ),
            (
                "VUID-VkBindImageMemoryInfo-None-01902",
                How::User(UNPROVEN_PROTECTED),
            ),
            (
                "VUID-VkBindImageMemoryInfo-memory-02728",
                How::Dynamic(MEMORY_KIND),
            ),
            (
                "VUID-VkBindImageMemoryInfo-memory-02729",
                How::Static(NO_IMPORT),
            ),
            (
                "VUID-VkBindImageMemoryDeviceGroupInfo-deviceIndexCount-01633",
                How::Dynamic(IMAGE_GROUP_SPLIT),
            ),
            (
                "VUID-VkBindImageMemoryDeviceGroupInfo-deviceIndexCount-01634",
                How::Dynamic(IMAGE_GROUP),
            ),
            (
                "VUID-VkBindImageMemoryDeviceGroupInfo-pDeviceIndices-01635",
                How::Dynamic(IMAGE_GROUP_ALONE),
            ),
            (
                "VUID-VkBindImageMemoryDeviceGroupInfo-splitInstanceBindRegionCount-01636",
                How::Dynamic(IMAGE_GROUP_SPLIT),
            ),
            (
                "VUID-VkBindImageMemoryInfo-pNext-01627",
                How::Dynamic(IMAGE_GROUP),
            ),
            (
                "VUID-VkBindImageMemoryInfo-pNext-01626",
                How::User(UNPROVEN_IMAGE_INSTANCES),
            ),
            (
                "VUID-VkBindImageMemoryDeviceGroupInfo-pSplitInstanceBindRegions-01637",
                How::User(SPLIT_REFUSED),
            ),
            (
                "VUID-VkBindImageMemoryDeviceGroupInfo-offset-01638",
                How::User(SPLIT_REFUSED),
            ),
            (
                "VUID-VkBindImageMemoryDeviceGroupInfo-offset-01639",
                How::User(SPLIT_REFUSED),
            ),
            (
                "VUID-VkBindImageMemoryDeviceGroupInfo-extent-01640",
                How::User(SPLIT_REFUSED),
            ),
            (
                "VUID-VkBindImageMemoryDeviceGroupInfo-extent-01641",
                How::User(SPLIT_REFUSED),
            ),
            (
                "VUID-VkBindImageMemoryInfo-pNext-01628",
                How::User(SPLIT_REFUSED),
            ),
            (
                "VUID-VkBindImageMemoryInfo-pNext-01629",
                How::User(SPLIT_REFUSED),
            ),
            (
                "VUID-vkBindImageMemory2-pBindInfos-02858",
                How::User(DISJOINT_REFUSED),
            ),
            (
                "VUID-VkBindImageMemoryInfo-image-07736",
                How::User(DISJOINT_REFUSED),
            ),
            (
                "VUID-VkBindImageMemoryInfo-pNext-01619",
                How::User(DISJOINT_REFUSED),
            ),
            (
                "VUID-VkBindImageMemoryInfo-pNext-01620",
                How::User(DISJOINT_REFUSED),
            ),
            (
                "VUID-VkBindImageMemoryInfo-pNext-01621",
                How::User(DISJOINT_REFUSED),
            ),
            (
                "VUID-VkBindImagePlaneMemoryInfo-planeAspect-02283",
                How::User(DISJOINT_REFUSED),
            ),
            (
                "VUID-VkBindImageMemoryInfo-image-01630",
                How::User(UNPROVEN_SWAPCHAIN_BIND),
            ),
            (
                "VUID-VkBindImageMemoryInfo-pNext-01631",
                How::User(UNPROVEN_SWAPCHAIN_BIND),
            ),
            (
                "VUID-VkBindImageMemoryInfo-pNext-01632",
                How::Static("the safe info's memory is a `DeviceMemory`, never VK_NULL_HANDLE"),
            ),
            (
                "VUID-VkBindImageMemorySwapchainInfoKHR-imageIndex-01644",
                How::User(UNPROVEN_SWAPCHAIN_BIND),
            ),
            (
                "VUID-VkBindImageMemorySwapchainInfoKHR-swapchain-07756",
                How::User(UNPROVEN_SWAPCHAIN_BIND),
            ),
        ],
        ..NONE
    },
    Special {
        command: "vkGetDeviceMemoryCommitment",
        check: call("special::memory::lazily_allocated", &["self", "memory"]),
        settles: &[(
            "VUID-vkGetDeviceMemoryCommitment-memory-00690",
            How::Dynamic(LAZY),
        )],
        ..NONE
    },
    Special {
        command: "vkGetImageMemoryRequirements2",
        check: call(
            "special::memory::image_requirements2_planes",
            &["self", "info"],
        ),
        settles: &[
            (
                "VUID-VkImageMemoryRequirementsInfo2-image-01589",
                How::User(UNPROVEN_DISJOINT),
            ),
            (
                "VUID-VkImageMemoryRequirementsInfo2-image-01590",
                How::Dynamic(PLANES),
            ),
            (
                "VUID-VkImageMemoryRequirementsInfo2-image-01591",
                How::User(UNPROVEN_DISJOINT),
            ),
            (
                "VUID-VkImagePlaneMemoryRequirementsInfo-planeAspect-02281",
                How::User(UNPROVEN_DISJOINT),
            ),
        ],
        ..NONE
    },
    Special {
        command: "vkGetImageMemoryRequirements",
        check: call(
            "special::memory::whole_image_requirements",
            &["self", "image"],
        ),
        settles: &[(
            "VUID-vkGetImageMemoryRequirements-image-01588",
            How::User(UNPROVEN_DISJOINT),
        )],
        ..NONE
    },
    Special {
        command: "vkBindImageMemory",
        check: call(
            "special::memory::bind_image_memory_checks",
            &["self", "image", "memory", "memory_offset"],
        ),
        after: call(
            "special::memory::bind_image_memory_done",
            &["self", "image", "memory", "memory_offset"],
        ),
        settles: &[
            (
                "VUID-vkBindImageMemory-image-07460",
                How::Dynamic(BIND_BOUND),
            ),
            ("VUID-vkBindImageMemory-image-01045", How::User(UNPROVEN)),
            (
                "VUID-vkBindImageMemory-memoryOffset-01046",
                How::Dynamic(BIND_MEMORY),
            ),
            ("VUID-vkBindImageMemory-memory-01047", How::User(UNPROVEN)),
            (
                "VUID-vkBindImageMemory-memoryOffset-01048",
                How::Dynamic(BIND_MEMORY),
            ),
            (
                "VUID-vkBindImageMemory-size-01049",
                How::Dynamic(BIND_MEMORY),
            ),
            ("VUID-vkBindImageMemory-image-01608", How::User(UNPROVEN)),
            (
                "VUID-vkBindImageMemory-image-01445",
                How::User(UNPROVEN_DEDICATED),
            ),
            (
                "VUID-vkBindImageMemory-memory-01509",
                How::Dynamic(MEMORY_KIND),
            ),
            (
                "VUID-vkBindImageMemory-None-01901",
                How::User(UNPROVEN_PROTECTED),
            ),
            (
                "VUID-vkBindImageMemory-None-01902",
                How::User(UNPROVEN_PROTECTED),
            ),
            (
                "VUID-vkBindImageMemory-memory-02728",
                How::Dynamic(MEMORY_KIND),
            ),
            (
                "VUID-vkBindImageMemory-memory-02729",
                How::Static(NO_IMPORT),
            ),
        ],
        ..NONE
    },
    Special {
        command: "vkAllocateMemory",
        check_last: call(
            "special::memory::allocate_memory_checks",
            &["self", "allocate_info"],
        ),
        hold: call("special::memory::allocate_memory_hold", &["self"]),
        keeps: Keeps::Nothing,
        created: call(
            "special::memory::memory_allocated",
            &["self", "created", "out", "allocate_info"],
        ),
        settles: &[
            (
                "VUID-vkAllocateMemory-pAllocateInfo-01714",
                How::Dynamic(MEMORY_TYPES),
            ),
            (
                "VUID-vkAllocateMemory-pAllocateInfo-01713",
                How::Dynamic(MEMORY_TYPES),
            ),
            (
                "VUID-VkMemoryAllocateInfo-flags-03330",
                How::Dynamic(MEMORY_TYPES),
            ),
            (
                "VUID-VkMemoryAllocateInfo-flags-03331",
                How::Dynamic(MEMORY_TYPES),
            ),
            (
                "VUID-VkMemoryAllocateInfo-opaqueCaptureAddress-03329",
                How::Dynamic(MEMORY_TYPES),
            ),
            (
                "VUID-VkMemoryAllocateInfo-memoryTypeIndex-01872",
                How::User(UNPROVEN_PROTECTED_TYPE),
            ),
            (
                "VUID-VkMemoryAllocateFlagsInfo-deviceMask-00675",
                How::Dynamic(DEVICE_MASK),
            ),
            (
                "VUID-VkMemoryAllocateFlagsInfo-deviceMask-00676",
                How::Dynamic(DEVICE_MASK),
            ),
            (
                "VUID-vkAllocateMemory-maxMemoryAllocationCount-04101",
                How::User(UNPROVEN_ALLOCATION_COUNT),
            ),
            (
                "VUID-VkMemoryDedicatedAllocateInfo-image-01432",
                How::Dynamic(DEDICATED),
            ),
            (
                "VUID-VkMemoryDedicatedAllocateInfo-image-01433",
                How::Dynamic(DEDICATED),
            ),
            (
                "VUID-VkMemoryDedicatedAllocateInfo-buffer-01435",
                How::Dynamic(DEDICATED),
            ),
            (
                "VUID-VkMemoryDedicatedAllocateInfo-image-01434",
                How::User(UNPROVEN_SPARSE_DEDICATED),
            ),
            (
                "VUID-VkMemoryDedicatedAllocateInfo-buffer-01436",
                How::User(UNPROVEN_SPARSE_DEDICATED),
            ),
            (
                "VUID-VkMemoryDedicatedAllocateInfo-image-01797",
                How::User(UNPROVEN_DISJOINT_DEDICATED),
            ),
            (
                "VUID-VkExportMemoryAllocateInfo-handleTypes-00656",
                How::Dynamic(EXPORT),
            ),
            (
                "VUID-VkMemoryAllocateInfo-None-06657",
                How::Static(NO_IMPORT),
            ),
            (
                "VUID-VkMemoryAllocateInfo-opaqueCaptureAddress-03333",
                How::Static(NO_IMPORT),
            ),
        ],
        ..NONE
    },
    Special {
        command: "vkMapMemory",
        settles: &[
            (
                "VUID-vkMapMemory-memory-00678",
                How::Dynamic("`DeviceMemory::map` refuses memory that a live `MappedMemory` maps"),
            ),
            (
                "VUID-vkMapMemory-memory-00682",
                How::Dynamic("`DeviceMemory::map` refuses memory whose type is not HOST_VISIBLE"),
            ),
            ("VUID-vkMapMemory-offset-00679", How::Static(WHOLE)),
            ("VUID-vkMapMemory-size-00680", How::Static(WHOLE)),
            ("VUID-vkMapMemory-size-00681", How::Static(WHOLE)),
        ],
        ..NONE
    },
    Special {
        command: "vkUnmapMemory",
        settles: &[(
            "VUID-vkUnmapMemory-memory-00689",
            How::Static("only a `MappedMemory` guard unmaps, once, the memory it mapped"),
        )],
        ..NONE
    },
];
