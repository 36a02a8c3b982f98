//! The special-case rows of one concern; their functions are the `tuff` crate's
//! `special/device.rs`, and a row here calls no other (but the image-layout tracker).
//!
//! Instances and devices: creation (extensions, features, device groups), the
//! scope their checks see, and private data.

use super::{call, How, Special, NONE};

const UNPROVEN_DISPLAY: &str = "checked by the safe methods in every build (the display's physical device against the device's), but no test breaks it: lavapipe enumerates no display";
const INSTANCE_INFO: &str = "checks each enabled extension's dependencies (vk.xml's `depends`, emitted as a table) against the enabled extensions and API version";
const INSTANCE_ALONE: &str = "checks the application's API version, and a chained messenger against the enabled extensions (proven by the error alone: the layer cannot speak through a messenger whose extension is off, and the 1.3.239 loader crashes once the layer has refused an API version below 1.0)";
const PRIVATE_TYPE: &str = "refuses an object type of the instance level (the 1.3.239 layer does not check it, and lavapipe crashes on it: proven by the error alone)";
const LIVE_OBJECT: &str =
    "checks the handle is the device or a live object of it of that type, which the device lists";
const NAMED_OBJECT: &str = "checks the handle is a live object of that type: the device, its instance or physical device, or an object the device lists (the `_unchecked` twin checks it too, as it finds the object's lock so: proven by the error alone)";
const UNPROVEN_PROTECTED_QUEUES: &str = "checked by the safe methods in every build (against the physical device's queue families), but no test breaks it: lavapipe has no protected queues, and a family is named twice only as protected and unprotected queues, so protectedMemory is refused first";
const DEVICE_QUEUES: &str = "checks the queue create infos against the physical device's queue families (index, count, protected capability), the priorities' range, each family named once, and the chain's feature structs against each other (features that come in pairs included) and against pEnabledFeatures";
const DEVICE_EXTENSIONS: &str = "checks each enabled extension's dependencies (vk.xml's `depends`) against the extensions of the device and its instance and the API version";
const DEVICE_GROUP: &str = "checks a chained device group create info names each physical device once, the one the device is created from among them, all in one group that the instance enumerates";
const UNPROVEN_DEVICE_GROUP: &str = "checked by the safe methods in every build, but no test breaks it: lavapipe has one physical device, the only member of its only device group";

/// The rows of this concern.
pub(super) const ROWS: &[Special] = &[
    // The generated common-parent check compares the display's physical device with
    // the device's.
    Special {
        command: "vkDisplayPowerControlEXT",
        settles: &[(
            "VUID-vkDisplayPowerControlEXT-commonparent",
            How::User(UNPROVEN_DISPLAY),
        )],
        ..NONE
    },
    // The generated common-parent check compares the display's physical device with
    // the device's.
    Special {
        command: "vkRegisterDisplayEventEXT",
        settles: &[(
            "VUID-vkRegisterDisplayEventEXT-commonparent",
            How::User(UNPROVEN_DISPLAY),
        )],
        ..NONE
    },
    Special {
        command: "vkSetPrivateData",
        check: call(
            "special::device::set_private_data_checks",
            &["self", "object_type", "object_handle"],
        ),
        settles: &[
            (
                "VUID-vkSetPrivateData-objectHandle-04016",
                How::Dynamic(LIVE_OBJECT),
            ),
            (
                "VUID-vkSetPrivateData-objectHandle-04017",
                How::Dynamic(LIVE_OBJECT),
            ),
        ],
        ..NONE
    },
    Special {
        command: "vkGetPrivateData",
        check: call(
            "special::device::get_private_data_checks",
            &["self", "object_type", "object_handle"],
        ),
        settles: &[(
            "VUID-vkGetPrivateData-objectType-04018",
            How::Dynamic(PRIVATE_TYPE),
        )],
        ..NONE
    },
    // Their host synchronization (plan::sync) looks the named object up among the
    // device's live objects and refuses one it does not find.
    Special {
        command: "vkSetDebugUtilsObjectNameEXT",
        settles: &[(
            "VUID-VkDebugUtilsObjectNameInfoEXT-objectType-02590",
            How::Dynamic(NAMED_OBJECT),
        )],
        ..NONE
    },
    Special {
        command: "vkSetDebugUtilsObjectTagEXT",
        settles: &[(
            "VUID-VkDebugUtilsObjectTagInfoEXT-objectHandle-01910",
            How::Dynamic(NAMED_OBJECT),
        )],
        ..NONE
    },
    Special {
        command: "vkCreateInstance",
        // The instance's own rules before the implicit ones: a messenger chained
        // without its extension is refused as the rule that names that case
        // (pNext-04926), not as the chain's general pNext-pNext.
        check: call("special::device::create_instance_first", &["create_info"]),
        created: call(
            "special::device::instance_created",
            &["self", "out", "create_info"],
        ),
        error: call(
            "diagnostics::presence::instance_error",
            &["self", "create_info", "r"],
        ),
        scope: call("special::device::create_instance_scope", &["create_info"]),
        settles: &[
            (
                "VUID-VkApplicationInfo-apiVersion-04010",
                How::Dynamic(INSTANCE_ALONE),
            ),
            (
                "VUID-vkCreateInstance-ppEnabledExtensionNames-01388",
                How::Dynamic(INSTANCE_INFO),
            ),
            (
                "VUID-VkInstanceCreateInfo-pNext-04926",
                How::Dynamic(INSTANCE_ALONE),
            ),
        ],
        ..NONE
    },
    Special {
        command: "vkCreateDevice",
        check_last: call(
            "special::device::create_device_checks",
            &["self", "create_info"],
        ),
        check: call(
            "special::device::device_extensions_emitted",
            &["create_info"],
        ),
        created: call(
            "special::device::device_created",
            &["self", "out", "create_info"],
        ),
        error: call(
            "diagnostics::presence::device_error",
            &["self", "create_info", "r"],
        ),
        scope: call(
            "special::device::create_device_scope",
            &["self", "create_info"],
        ),
        settles: &[
            (
                "VUID-VkDeviceCreateInfo-pNext-00373",
                How::Dynamic(DEVICE_QUEUES),
            ),
            (
                "VUID-VkDeviceCreateInfo-pNext-02829",
                How::Dynamic(DEVICE_QUEUES),
            ),
            (
                "VUID-VkDeviceCreateInfo-pNext-02830",
                How::Dynamic(DEVICE_QUEUES),
            ),
            (
                "VUID-VkDeviceCreateInfo-pNext-06532",
                How::Dynamic(DEVICE_QUEUES),
            ),
            (
                "VUID-VkDeviceQueueCreateInfo-queueFamilyIndex-00381",
                How::Dynamic(DEVICE_QUEUES),
            ),
            (
                "VUID-VkDeviceQueueCreateInfo-queueCount-00382",
                How::Dynamic(DEVICE_QUEUES),
            ),
            (
                "VUID-VkDeviceQueueCreateInfo-pQueuePriorities-00383",
                How::Dynamic(DEVICE_QUEUES),
            ),
            (
                "VUID-VkDeviceQueueCreateInfo-flags-02861",
                How::Dynamic(DEVICE_QUEUES),
            ),
            (
                "VUID-VkDeviceCreateInfo-queueFamilyIndex-02802",
                How::Dynamic(DEVICE_QUEUES),
            ),
            (
                "VUID-VkDeviceQueueCreateInfo-flags-06449",
                How::User(UNPROVEN_PROTECTED_QUEUES),
            ),
            (
                "VUID-VkDeviceCreateInfo-pQueueCreateInfos-06755",
                How::User(UNPROVEN_PROTECTED_QUEUES),
            ),
            (
                "VUID-vkCreateDevice-ppEnabledExtensionNames-01387",
                How::Dynamic(DEVICE_EXTENSIONS),
            ),
            (
                "VUID-VkPhysicalDeviceMultiviewFeatures-multiviewGeometryShader-00580",
                How::Dynamic(DEVICE_QUEUES),
            ),
            (
                "VUID-VkPhysicalDeviceMultiviewFeatures-multiviewTessellationShader-00581",
                How::Dynamic(DEVICE_QUEUES),
            ),
            (
                "VUID-VkPhysicalDeviceVariablePointersFeatures-variablePointers-01431",
                How::Dynamic(DEVICE_QUEUES),
            ),
            (
                "VUID-VkDeviceGroupDeviceCreateInfo-pPhysicalDevices-00375",
                How::Dynamic(DEVICE_GROUP),
            ),
            (
                "VUID-VkDeviceGroupDeviceCreateInfo-pPhysicalDevices-00376",
                How::User(UNPROVEN_DEVICE_GROUP),
            ),
            (
                "VUID-VkDeviceGroupDeviceCreateInfo-physicalDeviceCount-00377",
                How::User(UNPROVEN_DEVICE_GROUP),
            ),
        ],
        ..NONE
    },
];
