#include "engine/pipelines.h"

#include <array>
#include <vector>

#include "engine/gpu_structs.h"
#include "engine/resources.h"
#include "engine/types.h"
#include "engine/vk_check.h"
#include "shaders/spirv.h"

namespace cetview::engine {
namespace {

using shaders::ShaderId;

Result<VkRenderPass> createRenderPass(const Device& device, const TargetFormat& format) {
  bool msaa = format.samples != VK_SAMPLE_COUNT_1_BIT;
  std::vector<VkAttachmentDescription> attachments;

  VkAttachmentDescription color{};
  color.format = format.color;
  color.samples = format.samples;
  color.loadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;  // the background pass covers every pixel
  color.storeOp = msaa ? VK_ATTACHMENT_STORE_OP_DONT_CARE : VK_ATTACHMENT_STORE_OP_STORE;
  color.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  color.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  color.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  color.finalLayout = msaa ? VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL : format.finalLayout;
  attachments.push_back(color);

  VkAttachmentDescription depth{};
  depth.format = format.depth;
  depth.samples = format.samples;
  depth.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  depth.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  depth.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  depth.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  depth.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  depth.finalLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
  attachments.push_back(depth);

  if (msaa) {
    VkAttachmentDescription resolve = color;
    resolve.samples = VK_SAMPLE_COUNT_1_BIT;
    resolve.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    resolve.finalLayout = format.finalLayout;
    attachments.push_back(resolve);
  }

  VkAttachmentReference colorRef{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkAttachmentReference depthRef{1, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
  VkAttachmentReference resolveRef{2, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &colorRef;
  subpass.pResolveAttachments = msaa ? &resolveRef : nullptr;
  subpass.pDepthStencilAttachment = &depthRef;

  // In: the previous frame's use of the shared attachments (colour and depth writes, the capture's
  // transfer read of the output) finishes before this frame writes them; the swapchain image's
  // acquire semaphore is waited at colour output. Out: the capture copy or present reads after the
  // resolve/store.
  std::array<VkSubpassDependency, 2> dependencies{};
  dependencies[0].srcSubpass = VK_SUBPASS_EXTERNAL;
  dependencies[0].dstSubpass = 0;
  dependencies[0].srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT |
                                 VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT |
                                 VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT;
  dependencies[0].srcAccessMask =
      VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
  dependencies[0].dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT |
                                 VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT |
                                 VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
  dependencies[0].dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT |
                                  VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT |
                                  VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
  dependencies[1].srcSubpass = 0;
  dependencies[1].dstSubpass = VK_SUBPASS_EXTERNAL;
  dependencies[1].srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  dependencies[1].srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  dependencies[1].dstStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT;
  dependencies[1].dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;

  auto info = vkInit<VkRenderPassCreateInfo>(VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO);
  info.attachmentCount = static_cast<std::uint32_t>(attachments.size());
  info.pAttachments = attachments.data();
  info.subpassCount = 1;
  info.pSubpasses = &subpass;
  info.dependencyCount = static_cast<std::uint32_t>(dependencies.size());
  info.pDependencies = dependencies.data();
  VkRenderPass renderPass = VK_NULL_HANDLE;
  CETVIEW_VK(vkCreateRenderPass(device.device, &info, nullptr, &renderPass));
  return renderPass;
}

// Fixed-function state that differs between the four pipelines.
struct PipelineDesc {
  ShaderId vertex;
  ShaderId fragment;
  enum class Input { kNone, kMesh, kEdge } input;
  VkPrimitiveTopology topology;
  VkPolygonMode polygonMode;
  bool depthTest;
  bool depthWrite;
  bool depthBias;  // pushes faces back so lines on them win the depth test
  bool cullBack = false;
};

Result<VkPipeline> createPipeline(const Device& device, const Pipelines& p, const TargetFormat& format,
                                  const PipelineDesc& desc) {
  auto vertexCode = shaders::spirv(desc.vertex);
  auto fragmentCode = shaders::spirv(desc.fragment);
  auto vertexModule = createShaderModule(device, vertexCode.words, vertexCode.sizeBytes);
  CETVIEW_TRY(vertexModule);
  auto fragmentModule = createShaderModule(device, fragmentCode.words, fragmentCode.sizeBytes);
  if (!fragmentModule) {
    vkDestroyShaderModule(device.device, *vertexModule, nullptr);
    return fragmentModule.error();
  }

  // The same constants for every stage; a shader without one of them ignores it. Two-sided
  // lighting wherever back faces are not culled.
  const std::array<VkBool32, 2> specValues{isSrgbFormat(format.color) ? VK_FALSE : VK_TRUE,
                                           desc.cullBack ? VK_FALSE : VK_TRUE};
  const std::array<VkSpecializationMapEntry, 2> specEntries{
      VkSpecializationMapEntry{CETVIEW_SPEC_ENCODE_SRGB, 0, sizeof(VkBool32)},
      VkSpecializationMapEntry{CETVIEW_SPEC_TWO_SIDED, sizeof(VkBool32), sizeof(VkBool32)}};
  VkSpecializationInfo spec{static_cast<std::uint32_t>(specEntries.size()), specEntries.data(),
                            sizeof(specValues), specValues.data()};

  std::array<VkPipelineShaderStageCreateInfo, 2> stages{};
  stages[0].sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
  stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
  stages[0].module = *vertexModule;
  stages[0].pName = "main";
  stages[0].pSpecializationInfo = &spec;
  stages[1] = stages[0];
  stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
  stages[1].module = *fragmentModule;

  VkVertexInputBindingDescription binding{0, 0, VK_VERTEX_INPUT_RATE_VERTEX};
  std::array<VkVertexInputAttributeDescription, 2> attributes{};
  auto vertexInput =
      vkInit<VkPipelineVertexInputStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO);
  if (desc.input == PipelineDesc::Input::kMesh) {
    binding.stride = sizeof(MeshVertex);
    attributes[0] = {0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(MeshVertex, position)};
    attributes[1] = {1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(MeshVertex, normal)};
    vertexInput.vertexBindingDescriptionCount = 1;
    vertexInput.pVertexBindingDescriptions = &binding;
    vertexInput.vertexAttributeDescriptionCount = 2;
    vertexInput.pVertexAttributeDescriptions = attributes.data();
  } else if (desc.input == PipelineDesc::Input::kEdge) {
    binding.stride = 3 * sizeof(float);
    attributes[0] = {0, 0, VK_FORMAT_R32G32B32_SFLOAT, 0};
    vertexInput.vertexBindingDescriptionCount = 1;
    vertexInput.pVertexBindingDescriptions = &binding;
    vertexInput.vertexAttributeDescriptionCount = 1;
    vertexInput.pVertexAttributeDescriptions = attributes.data();
  }

  auto assembly = vkInit<VkPipelineInputAssemblyStateCreateInfo>(
      VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO);
  assembly.topology = desc.topology;

  auto viewport =
      vkInit<VkPipelineViewportStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO);
  viewport.viewportCount = 1;
  viewport.scissorCount = 1;

  auto raster = vkInit<VkPipelineRasterizationStateCreateInfo>(
      VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO);
  raster.polygonMode = desc.polygonMode;
  // CAD faces have no reliable winding in general; lighting is two-sided. Closed solids promise
  // counter-clockwise outsides (Scene::addPart) and drop their back faces early.
  raster.cullMode = desc.cullBack ? VK_CULL_MODE_BACK_BIT : VK_CULL_MODE_NONE;
  raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
  raster.lineWidth = 1.0f;
  raster.depthBiasEnable = desc.depthBias ? VK_TRUE : VK_FALSE;
  raster.depthBiasConstantFactor = 1.0f;
  raster.depthBiasSlopeFactor = 1.0f;

  auto multisample =
      vkInit<VkPipelineMultisampleStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO);
  multisample.rasterizationSamples = format.samples;

  auto depth = vkInit<VkPipelineDepthStencilStateCreateInfo>(
      VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO);
  depth.depthTestEnable = desc.depthTest ? VK_TRUE : VK_FALSE;
  depth.depthWriteEnable = desc.depthWrite ? VK_TRUE : VK_FALSE;
  depth.depthCompareOp = VK_COMPARE_OP_LESS_OR_EQUAL;

  VkPipelineColorBlendAttachmentState blendAttachment{};
  blendAttachment.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT |
                                   VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
  auto blend =
      vkInit<VkPipelineColorBlendStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO);
  blend.attachmentCount = 1;
  blend.pAttachments = &blendAttachment;

  std::array<VkDynamicState, 2> dynamicStates{VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
  auto dynamic =
      vkInit<VkPipelineDynamicStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO);
  dynamic.dynamicStateCount = static_cast<std::uint32_t>(dynamicStates.size());
  dynamic.pDynamicStates = dynamicStates.data();

  auto info = vkInit<VkGraphicsPipelineCreateInfo>(VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO);
  info.stageCount = static_cast<std::uint32_t>(stages.size());
  info.pStages = stages.data();
  info.pVertexInputState = &vertexInput;
  info.pInputAssemblyState = &assembly;
  info.pViewportState = &viewport;
  info.pRasterizationState = &raster;
  info.pMultisampleState = &multisample;
  info.pDepthStencilState = &depth;
  info.pColorBlendState = &blend;
  info.pDynamicState = &dynamic;
  info.layout = p.layout;
  info.renderPass = p.renderPass;
  info.subpass = 0;
  VkPipeline pipeline = VK_NULL_HANDLE;
  VkResult r = vkCreateGraphicsPipelines(device.device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline);
  vkDestroyShaderModule(device.device, *vertexModule, nullptr);
  vkDestroyShaderModule(device.device, *fragmentModule, nullptr);
  if (r != VK_SUCCESS) return vkError("vkCreateGraphicsPipelines", r);
  return pipeline;
}

Status createLayouts(const Device& device, Pipelines& p) {
  constexpr VkShaderStageFlags kStages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
  std::array<VkDescriptorSetLayoutBinding, 2> bindings{};
  bindings[0] = {CETVIEW_BINDING_GLOBALS, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, kStages, nullptr};
  bindings[1] = {CETVIEW_BINDING_FACES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, kStages, nullptr};
  auto setInfo = vkInit<VkDescriptorSetLayoutCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO);
  setInfo.bindingCount = static_cast<std::uint32_t>(bindings.size());
  setInfo.pBindings = bindings.data();
  CETVIEW_VK(vkCreateDescriptorSetLayout(device.device, &setInfo, nullptr, &p.setLayout));

  VkPushConstantRange push{kStages, 0, sizeof(DrawConstants)};
  auto layoutInfo = vkInit<VkPipelineLayoutCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO);
  layoutInfo.setLayoutCount = 1;
  layoutInfo.pSetLayouts = &p.setLayout;
  layoutInfo.pushConstantRangeCount = 1;
  layoutInfo.pPushConstantRanges = &push;
  CETVIEW_VK(vkCreatePipelineLayout(device.device, &layoutInfo, nullptr, &p.layout));
  return {};
}

// The render pass and every pipeline; the layouts must exist.
Status createPassAndPipelines(const Device& device, const TargetFormat& format, Pipelines& p) {
  auto renderPass = createRenderPass(device, format);
  CETVIEW_TRY(renderPass);
  p.renderPass = *renderPass;

  using Input = PipelineDesc::Input;
  constexpr auto kTriangles = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  auto background = createPipeline(device, p, format,
                                   {ShaderId::kBackgroundVert, ShaderId::kBackgroundFrag, Input::kNone,
                                    kTriangles, VK_POLYGON_MODE_FILL, false, false, false});
  CETVIEW_TRY(background);
  p.background = *background;
  // One colour per draw (one-by-one draws): the shaders without a colour varying.
  const ShaderId meshVert = p.colorPushed ? ShaderId::kMeshPushedVert : ShaderId::kMeshVert;
  PipelineDesc shadedDesc{meshVert,
                          p.colorPushed ? ShaderId::kMeshPushedFrag : ShaderId::kMeshFrag,
                          Input::kMesh,
                          kTriangles,
                          VK_POLYGON_MODE_FILL,
                          true,
                          true,
                          true};
  auto shaded = createPipeline(device, p, format, shadedDesc);
  CETVIEW_TRY(shaded);
  p.shaded = *shaded;
  PipelineDesc culledDesc = shadedDesc;
  culledDesc.cullBack = true;
  auto shadedCulled = createPipeline(device, p, format, culledDesc);
  CETVIEW_TRY(shadedCulled);
  p.shadedCulled = *shadedCulled;
  if (device.features.fillModeNonSolid) {
    PipelineDesc wireDesc{meshVert,
                          p.colorPushed ? ShaderId::kWirePushedFrag : ShaderId::kWireFrag,
                          Input::kMesh,
                          kTriangles,
                          VK_POLYGON_MODE_LINE,
                          true,
                          true,
                          false};
    auto wireframe = createPipeline(device, p, format, wireDesc);
    CETVIEW_TRY(wireframe);
    p.wireframe = *wireframe;
  }
  auto edges = createPipeline(device, p, format,
                              {ShaderId::kEdgeVert, ShaderId::kEdgeFrag, Input::kEdge,
                               VK_PRIMITIVE_TOPOLOGY_LINE_LIST, VK_POLYGON_MODE_FILL, true, false, false});
  CETVIEW_TRY(edges);
  p.edges = *edges;
  return {};
}

// Destroys the render pass and the pipelines, keeping the layouts.
void destroyPassAndPipelines(const Device& device, Pipelines& p) {
  for (VkPipeline* pipeline : {&p.background, &p.shaded, &p.shadedCulled, &p.wireframe, &p.edges}) {
    if (*pipeline != VK_NULL_HANDLE) vkDestroyPipeline(device.device, *pipeline, nullptr);
    *pipeline = VK_NULL_HANDLE;
  }
  if (p.renderPass != VK_NULL_HANDLE) vkDestroyRenderPass(device.device, p.renderPass, nullptr);
  p.renderPass = VK_NULL_HANDLE;
}

}  // namespace

Result<Pipelines> createPipelines(const Device& device, const TargetFormat& format, bool colorPushed) {
  Pipelines p;
  p.colorPushed = colorPushed;
  Status status = createLayouts(device, p);
  if (status) status = createPassAndPipelines(device, format, p);
  if (!status) {
    destroyPipelines(device, p);
    return status.error();
  }
  return p;
}

Status recreatePipelines(const Device& device, const TargetFormat& format, Pipelines& p) {
  destroyPassAndPipelines(device, p);
  return createPassAndPipelines(device, format, p);
}

void destroyPipelines(const Device& device, Pipelines& p) {
  destroyPassAndPipelines(device, p);
  if (p.layout != VK_NULL_HANDLE) vkDestroyPipelineLayout(device.device, p.layout, nullptr);
  if (p.setLayout != VK_NULL_HANDLE) vkDestroyDescriptorSetLayout(device.device, p.setLayout, nullptr);
  p = Pipelines{};
}

Result<VkFormat> chooseDepthFormat(const Device& device) {
  for (VkFormat format : {VK_FORMAT_D32_SFLOAT, VK_FORMAT_D24_UNORM_S8_UINT, VK_FORMAT_D16_UNORM}) {
    VkFormatProperties props;
    vkGetPhysicalDeviceFormatProperties(device.physicalDevice, format, &props);
    if (props.optimalTilingFeatures & VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT) return format;
  }
  return makeError(ErrorCode::kUnsupported, "the device supports no depth attachment format");
}

VkSampleCountFlagBits chooseSampleCount(const Device& device, std::uint32_t requested) {
  const VkPhysicalDeviceLimits& limits = device.properties.limits;
  VkSampleCountFlags supported = limits.framebufferColorSampleCounts & limits.framebufferDepthSampleCounts;
  for (std::uint32_t count = 64; count > 1; count /= 2) {
    if (count <= requested && (supported & count)) return static_cast<VkSampleCountFlagBits>(count);
  }
  return VK_SAMPLE_COUNT_1_BIT;
}

bool preferSrgbTarget(const Device& device, VkSampleCountFlagBits samples) {
  return device.properties.deviceType != VK_PHYSICAL_DEVICE_TYPE_CPU || samples != VK_SAMPLE_COUNT_1_BIT;
}

bool isSrgbFormat(VkFormat format) {
  switch (format) {
    case VK_FORMAT_R8G8B8A8_SRGB:
    case VK_FORMAT_B8G8R8A8_SRGB:
    case VK_FORMAT_A8B8G8R8_SRGB_PACK32:
    case VK_FORMAT_R8G8B8_SRGB:
    case VK_FORMAT_B8G8R8_SRGB:
      return true;
    default:
      return false;
  }
}

}  // namespace cetview::engine
