#include <glint/core/error.h>
#include <glint/denoise/network.h>

#include <fmt/format.h>
#include <omp.h>

#include <oneapi/dnnl/dnnl.hpp>

#include <algorithm>
#include <limits>
#include <unordered_map>

namespace glint {

namespace {

using dnnl::memory;
using Tag = memory::format_tag;

// A step of the plan: a primitive and its arguments.
struct Step {
    dnnl::primitive primitive;
    std::unordered_map<int, memory> args;
};

// A block of bytes shared by the activations that are alive at different times.
struct Arena {
    std::size_t bytes = 0;
    std::unique_ptr<char[]> storage;  // over-allocated by 64 for alignment
    char* data() const {
        auto address = reinterpret_cast<std::uintptr_t>(storage.get());
        return reinterpret_cast<char*>((address + 63) & ~std::uintptr_t{63});
    }
};

Tag blocked_tag() {
    const dnnl::cpu_isa isa = dnnl::get_effective_cpu_isa();
    const bool avx512 =
        isa == dnnl::cpu_isa::avx512_core || isa == dnnl::cpu_isa::avx512_core_vnni ||
        isa == dnnl::cpu_isa::avx512_core_bf16 || isa == dnnl::cpu_isa::avx512_core_amx;
    return avx512 ? Tag::nChw16c : Tag::nChw8c;
}

// The planar [out][in][3][3] weights restricted to input channels [first, first + count).
std::vector<float> weight_slice(const Layer& layer, int in_channels, int first, int count) {
    std::vector<float> slice(static_cast<std::size_t>(layer.channels) * count * 9);
    for (int o = 0; o < layer.channels; ++o)
        for (int i = 0; i < count; ++i)
            std::copy_n(layer.weights.begin() +
                            (static_cast<std::ptrdiff_t>(o) * in_channels + first + i) * 9,
                        9, slice.begin() + (static_cast<std::ptrdiff_t>(o) * count + i) * 9);
    return slice;
}

}  // namespace

struct NetworkExecutor::Impl {
    dnnl::engine engine{dnnl::engine::kind::cpu, 0};
    dnnl::stream stream{engine};
    int threads = 1;
    int height = 0, width = 0;
    Tag tag = Tag::nChw8c;
    std::vector<memory::desc> descs;  // per layer (Concat: unused)
    std::vector<memory> tensors;      // per layer, in an arena (Concat: none)
    std::vector<Arena> arenas;
    std::vector<memory> owned;  // weights, biases, reorder targets, scratchpads
    std::vector<Step> steps;
    std::size_t owned_bytes = 0;
    memory::desc output_desc;

    memory::dims dims_of(const Layer& layer) const {
        return {1, layer.channels, height >> layer.level, width >> layer.level};
    }
    memory own(const memory::desc& desc) {
        owned.emplace_back(desc, engine);
        owned_bytes += desc.get_size();
        return owned.back();
    }
    memory own_copy(const memory::desc& plain, const memory::desc& wanted,
                    const std::vector<float>& data) {
        memory source(plain, engine, const_cast<float*>(data.data()));
        memory target = own(wanted);
        dnnl::reorder(source, target).execute(stream, source, target);
        stream.wait();
        return target;
    }
    std::vector<std::pair<std::size_t, memory::desc>> scratch;  // step -> its scratchpad
    Arena scratch_arena;
    memory::desc input_desc;
    std::size_t output_layer = 0;
    int output_channels = 0, output_level = 0;

    void plan_tensors(const NetworkGraph& graph);
    void add_conv(std::size_t index, const Layer& layer, int source, int in_channels, int first,
                  bool first_part, bool relu);
    void add_layer(const NetworkGraph& graph, std::size_t index);
    void share_scratchpad();
};

// Gives each tensor a place in an arena: a tensor's arena is free again after its last
// reader ran (a Concat's parts are read by the convolution after it), and a new tensor
// takes the smallest free arena, enlarging it when none is big enough.
void NetworkExecutor::Impl::plan_tensors(const NetworkGraph& graph) {
    const std::size_t count = graph.layers.size();
    std::vector<std::size_t> last_use(count, 0);
    for (std::size_t i = 0; i < count; ++i) {
        for (int input : graph.layers[i].inputs) last_use[static_cast<std::size_t>(input)] = i;
    }
    for (std::size_t i = 0; i < count; ++i) {
        if (graph.layers[i].kind == LayerKind::Concat) {
            for (int part : graph.layers[i].inputs)
                last_use[static_cast<std::size_t>(part)] = last_use[i];
        }
    }
    last_use[count - 1] = std::numeric_limits<std::size_t>::max();
    std::vector<int> arena_of(count, -1);
    std::vector<int> holder;  // arena -> layer now in it, -1 when free
    for (std::size_t i = 0; i < count; ++i) {
        descs.push_back(memory::desc(dims_of(graph.layers[i]), memory::data_type::f32, tag));
        for (std::size_t a = 0; a < holder.size(); ++a) {
            if (holder[a] >= 0 && last_use[static_cast<std::size_t>(holder[a])] < i) holder[a] = -1;
        }
        if (graph.layers[i].kind == LayerKind::Concat) continue;
        const std::size_t bytes = descs[i].get_size();
        int best = -1;
        for (std::size_t a = 0; a < holder.size(); ++a) {
            if (holder[a] >= 0) continue;
            const bool fits = arenas[a].bytes >= bytes;
            if (best < 0 ||
                (fits && (arenas[static_cast<std::size_t>(best)].bytes < bytes ||
                          arenas[a].bytes < arenas[static_cast<std::size_t>(best)].bytes)) ||
                (!fits && arenas[static_cast<std::size_t>(best)].bytes < bytes &&
                 arenas[a].bytes > arenas[static_cast<std::size_t>(best)].bytes))
                best = static_cast<int>(a);
        }
        if (best < 0) {
            arenas.emplace_back();
            holder.push_back(-1);
            best = static_cast<int>(arenas.size()) - 1;
        }
        Arena& arena = arenas[static_cast<std::size_t>(best)];
        arena.bytes = std::max(arena.bytes, bytes);
        holder[static_cast<std::size_t>(best)] = static_cast<int>(i);
        arena_of[i] = best;
    }
    for (Arena& arena : arenas) arena.storage = std::make_unique<char[]>(arena.bytes + 64);
    tensors.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
        if (arena_of[i] >= 0)
            tensors[i] =
                memory(descs[i], engine, arenas[static_cast<std::size_t>(arena_of[i])].data());
    }
}

// One 3 x 3 convolution into the tensor of layer `index`, reading tensor `source` with the
// weights of the layer's input channels [first, first + in_channels). The second part of a
// concatenation adds onto the first part's result (`accumulate`), without a second bias.
void NetworkExecutor::Impl::add_conv(std::size_t index, const Layer& layer, int source,
                                     int in_channels, int first, bool first_part, bool relu) {
    const auto f32 = memory::data_type::f32;
    const memory::desc& source_desc = descs[static_cast<std::size_t>(source)];
    const memory::desc src_any({1, in_channels, source_desc.dims()[2], source_desc.dims()[3]}, f32,
                               Tag::any);
    const memory::desc weights_any({layer.channels, in_channels, 3, 3}, f32, Tag::any);
    const memory::desc bias_desc({layer.channels}, f32, Tag::x);
    dnnl::post_ops ops;
    if (!first_part) ops.append_sum(1.f);
    if (relu) ops.append_eltwise(1.f, dnnl::algorithm::eltwise_relu, 0.f, 0.f);
    dnnl::primitive_attr attr;
    attr.set_post_ops(ops);
    attr.set_scratchpad_mode(dnnl::scratchpad_mode::user);
    const memory::dims one{1, 1}, pad{1, 1};
    const auto desc =
        first_part ? dnnl::convolution_forward::desc(
                         dnnl::prop_kind::forward_inference, dnnl::algorithm::convolution_direct,
                         src_any, weights_any, bias_desc, descs[index], one, pad, pad)
                   : dnnl::convolution_forward::desc(dnnl::prop_kind::forward_inference,
                                                     dnnl::algorithm::convolution_direct, src_any,
                                                     weights_any, descs[index], one, pad, pad);
    const dnnl::convolution_forward::primitive_desc pd(desc, attr, engine);
    memory src = tensors[static_cast<std::size_t>(source)];
    if (pd.src_desc() != source_desc) {
        // A layout the kernel prefers for this tensor (e.g. the input's few channels).
        memory converted = own(pd.src_desc());
        steps.push_back(
            {dnnl::reorder(src, converted), {{DNNL_ARG_FROM, src}, {DNNL_ARG_TO, converted}}});
        src = converted;
    }
    const int all_inputs =
        static_cast<int>(layer.weights.size() / 9 / static_cast<std::size_t>(layer.channels));
    const std::vector<float> slice = weight_slice(layer, all_inputs, first, in_channels);
    Step step{dnnl::convolution_forward(pd), {}};
    step.args[DNNL_ARG_SRC] = src;
    step.args[DNNL_ARG_WEIGHTS] =
        own_copy(memory::desc({layer.channels, in_channels, 3, 3}, f32, Tag::oihw),
                 pd.weights_desc(), slice);
    if (first_part) step.args[DNNL_ARG_BIAS] = own_copy(bias_desc, pd.bias_desc(), layer.bias);
    step.args[DNNL_ARG_DST] = tensors[index];
    scratch.emplace_back(steps.size(), pd.scratchpad_desc());
    steps.push_back(std::move(step));
}

void NetworkExecutor::Impl::add_layer(const NetworkGraph& graph, std::size_t index) {
    const Layer& layer = graph.layers[index];
    const memory::dims two{2, 2}, zero{0, 0};
    switch (layer.kind) {
        case LayerKind::Input:
            if (index != 0) throw Error("a network's input must be its first layer");
            break;
        case LayerKind::Conv: {
            const int source = layer.inputs[0];
            const Layer& input = graph.layers[static_cast<std::size_t>(source)];
            if (input.kind != LayerKind::Concat) {
                add_conv(index, layer, source, input.channels, 0, true, layer.relu);
                break;
            }
            const int a = input.inputs[0], b = input.inputs[1];
            const int a_channels = graph.layers[static_cast<std::size_t>(a)].channels;
            add_conv(index, layer, a, a_channels, 0, true, false);
            add_conv(index, layer, b, graph.layers[static_cast<std::size_t>(b)].channels,
                     a_channels, false, layer.relu);
            break;
        }
        case LayerKind::Pool: {
            const std::size_t source = static_cast<std::size_t>(layer.inputs[0]);
            dnnl::primitive_attr attr;
            attr.set_scratchpad_mode(dnnl::scratchpad_mode::user);
            const dnnl::pooling_forward::primitive_desc pd(
                dnnl::pooling_forward::desc(dnnl::prop_kind::forward_inference,
                                            dnnl::algorithm::pooling_max, descs[source],
                                            descs[index], two, two, zero, zero),
                attr, engine);
            scratch.emplace_back(steps.size(), pd.scratchpad_desc());
            steps.push_back({dnnl::pooling_forward(pd),
                             {{DNNL_ARG_SRC, tensors[source]}, {DNNL_ARG_DST, tensors[index]}}});
            break;
        }
        case LayerKind::Upsample: {
            const std::size_t source = static_cast<std::size_t>(layer.inputs[0]);
            dnnl::primitive_attr attr;
            attr.set_scratchpad_mode(dnnl::scratchpad_mode::user);
            const dnnl::resampling_forward::primitive_desc pd(
                dnnl::resampling_forward::desc(dnnl::prop_kind::forward_inference,
                                               dnnl::algorithm::resampling_nearest, descs[source],
                                               descs[index]),
                attr, engine);
            scratch.emplace_back(steps.size(), pd.scratchpad_desc());
            steps.push_back({dnnl::resampling_forward(pd),
                             {{DNNL_ARG_SRC, tensors[source]}, {DNNL_ARG_DST, tensors[index]}}});
            break;
        }
        case LayerKind::Concat:
            // Read by the convolution after it, part by part; nothing else may read it.
            if (index + 1 >= graph.layers.size())
                throw Error(fmt::format("'{}': a concatenation cannot be the network's output",
                                        layer.name));
            for (std::size_t j = index + 1; j < graph.layers.size(); ++j) {
                const Layer& reader = graph.layers[j];
                const bool reads = std::find(reader.inputs.begin(), reader.inputs.end(),
                                             static_cast<int>(index)) != reader.inputs.end();
                if (reads && reader.kind != LayerKind::Conv)
                    throw Error(fmt::format("'{}': only a convolution may read a concatenation",
                                            layer.name));
            }
            break;
    }
}

// One scratchpad, as large as the largest any primitive asks for, shared by all of them
// (they run one after another).
void NetworkExecutor::Impl::share_scratchpad() {
    std::size_t bytes = 0;
    for (const auto& [step, desc] : scratch) bytes = std::max(bytes, desc.get_size());
    scratch_arena.bytes = bytes;
    scratch_arena.storage = std::make_unique<char[]>(bytes + 64);
    for (const auto& [step, desc] : scratch) {
        if (desc.get_size() > 0)
            steps[step].args[DNNL_ARG_SCRATCHPAD] = memory(desc, engine, scratch_arena.data());
    }
}

NetworkExecutor::NetworkExecutor(const NetworkGraph& graph, int height, int width, int threads)
    : m_impl(std::make_unique<Impl>()) {
    const int step = 1 << graph.max_level();
    if (graph.layers.empty() || height <= 0 || width <= 0 || height % step != 0 ||
        width % step != 0)
        throw Error(
            fmt::format("the network needs an input of sides that are positive multiples of {} "
                        "(got {} x {})",
                        step, width, height));
    if (threads < 1)
        throw Error(fmt::format("the network needs at least 1 thread (got {})", threads));
    Impl& impl = *m_impl;
    impl.threads = threads;
    impl.height = height;
    impl.width = width;
    impl.tag = blocked_tag();
    // oneDNN's kernels divide their work by the thread count they see when created.
    omp_set_num_threads(threads);
    try {
        impl.plan_tensors(graph);
        for (std::size_t i = 0; i < graph.layers.size(); ++i) impl.add_layer(graph, i);
        impl.share_scratchpad();
        const Layer& first = graph.layers.front();
        impl.input_desc = memory::desc(impl.dims_of(first), memory::data_type::f32, Tag::nchw);
        impl.output_desc =
            memory::desc(impl.dims_of(graph.output()), memory::data_type::f32, Tag::nchw);
        impl.output_layer = graph.layers.size() - 1;
        impl.output_channels = graph.output().channels;
        impl.output_level = graph.output().level;
    } catch (const dnnl::error& e) {
        throw Error(fmt::format("oneDNN cannot set up the denoiser network: {}", e.what()));
    }
}

NetworkExecutor::~NetworkExecutor() = default;

void NetworkExecutor::run(const float* input, float* output) {
    Impl& impl = *m_impl;
    omp_set_num_threads(impl.threads);
    try {
        memory in(impl.input_desc, impl.engine, const_cast<float*>(input));
        dnnl::reorder(in, impl.tensors[0]).execute(impl.stream, in, impl.tensors[0]);
        for (Step& step : impl.steps) step.primitive.execute(impl.stream, step.args);
        memory out(impl.output_desc, impl.engine, output);
        dnnl::reorder(impl.tensors[impl.output_layer], out)
            .execute(impl.stream, impl.tensors[impl.output_layer], out);
        impl.stream.wait();
    } catch (const dnnl::error& e) {
        throw Error(fmt::format("oneDNN failed while running the denoiser network: {}", e.what()));
    }
}

int NetworkExecutor::output_channels() const {
    return m_impl->output_channels;
}
int NetworkExecutor::output_height() const {
    return m_impl->height >> m_impl->output_level;
}
int NetworkExecutor::output_width() const {
    return m_impl->width >> m_impl->output_level;
}

std::size_t NetworkExecutor::memory_bytes() const {
    std::size_t bytes = m_impl->owned_bytes + m_impl->scratch_arena.bytes;
    for (const Arena& arena : m_impl->arenas) bytes += arena.bytes;
    return bytes;
}

}  // namespace glint
