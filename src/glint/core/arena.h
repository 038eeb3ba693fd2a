#pragma once
// Per-thread bump allocator for short-lived objects (BSDFs built at each hit). Reset once
// per sample, so the render loop never touches the heap.
#include <cstddef>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace glint {

class Arena {
public:
    explicit Arena(size_t block_size = 64 * 1024) : m_block_size(block_size) {}
    Arena(const Arena&) = delete;
    Arena& operator=(const Arena&) = delete;
    Arena(Arena&&) = default;
    Arena& operator=(Arena&&) = default;

    template <typename T, typename... Args>
    T* make(Args&&... args) {
        static_assert(std::is_trivially_destructible_v<T>,
                      "arena objects are never destroyed, so they must be trivially destructible");
        void* memory = allocate(sizeof(T), alignof(T));
        return new (memory) T(std::forward<Args>(args)...);
    }

    void reset() {
        m_block = 0;
        m_offset = 0;
    }

private:
    void* allocate(size_t size, size_t align) {
        if (size + align > m_block_size) throw std::bad_alloc();
        for (;;) {
            if (m_block < m_blocks.size()) {
                const size_t start = (m_offset + align - 1) & ~(align - 1);
                if (start + size <= m_block_size) {
                    m_offset = start + size;
                    return m_blocks[m_block].get() + start;
                }
                ++m_block;
                m_offset = 0;
                continue;
            }
            m_blocks.push_back(std::make_unique<std::byte[]>(m_block_size));
        }
    }

    size_t m_block_size;
    std::vector<std::unique_ptr<std::byte[]>> m_blocks;
    size_t m_block = 0;
    size_t m_offset = 0;
};

}  // namespace glint
