// ECS storage: entities are ids, components are plain structs in dense arrays (sparse sets),
// resources are per-world singletons (the ocean, the renderer's inputs, the input state).
#pragma once
#include <cassert>
#include <cstdint>
#include <memory>
#include <typeindex>
#include <unordered_map>
#include <vector>

namespace ob::ecs {

/// An entity id; 0 is never a valid entity.
enum class Entity : uint32_t { None = 0 };

/// Dense storage for one component type: components packed in creation order.
/// Iteration order is insertion order, so systems run deterministically.
template <class T>
class Pool {
public:
    T& add(Entity e, T value) {
        uint32_t id = uint32_t(e);
        if (id >= m_sparse.size()) m_sparse.resize(id + 1, NONE);
        assert(m_sparse[id] == NONE && "component added twice");
        m_sparse[id] = uint32_t(m_dense.size());
        m_entities.push_back(e);
        m_dense.push_back(std::move(value));
        return m_dense.back();
    }
    void remove(Entity e) {
        uint32_t id = uint32_t(e);
        if (!has(e)) return;
        // Shift (not swap) so the remaining order, and hence every result, stays stable.
        uint32_t slot = m_sparse[id];
        m_dense.erase(m_dense.begin() + slot);
        m_entities.erase(m_entities.begin() + slot);
        m_sparse[id] = NONE;
        for (uint32_t i = slot; i < m_entities.size(); ++i) m_sparse[uint32_t(m_entities[i])] = i;
    }
    bool has(Entity e) const { return uint32_t(e) < m_sparse.size() && m_sparse[uint32_t(e)] != NONE; }
    T& get(Entity e) { assert(has(e)); return m_dense[m_sparse[uint32_t(e)]]; }
    const T& get(Entity e) const { assert(has(e)); return m_dense[m_sparse[uint32_t(e)]]; }
    T* find(Entity e) { return has(e) ? &m_dense[m_sparse[uint32_t(e)]] : nullptr; }
    size_t size() const { return m_dense.size(); }
    /// Components, densely packed; entities()[i] owns components()[i].
    std::vector<T>& components() { return m_dense; }
    const std::vector<T>& components() const { return m_dense; }
    const std::vector<Entity>& entities() const { return m_entities; }

private:
    static constexpr uint32_t NONE = ~0u;
    std::vector<uint32_t> m_sparse;
    std::vector<Entity> m_entities;
    std::vector<T> m_dense;
};

/// The world: entity ids, one Pool per component type, and typed resources.
class World {
public:
    /// A new entity id (ids are never reused within a world).
    Entity create() { return Entity(++m_lastId); }
    /// Removes every component of `e` (the id stays retired).
    void destroy(Entity e) {
        for (auto& [type, slot] : m_pools) slot.remove(slot.object.get(), e);
    }
    uint32_t entityCount() const { return m_lastId; }

    template <class T> Pool<T>& pool() {
        auto& slot = m_pools[std::type_index(typeid(T))];
        if (!slot.object) {
            slot.object = std::shared_ptr<void>(new Pool<T>(), [](void* p) { delete static_cast<Pool<T>*>(p); });
            slot.remove = [](void* p, Entity e) { static_cast<Pool<T>*>(p)->remove(e); };
        }
        return *static_cast<Pool<T>*>(slot.object.get());
    }
    template <class T> T& add(Entity e, T value = {}) { return pool<T>().add(e, std::move(value)); }
    template <class T> T& get(Entity e) { return pool<T>().get(e); }
    template <class T> T* find(Entity e) { return pool<T>().find(e); }
    template <class T> bool has(Entity e) { return pool<T>().has(e); }

    /// Stores a resource (a per-world singleton), replacing any previous one of that type.
    template <class T> T& setResource(std::unique_ptr<T> value) {
        T* raw = value.get();
        m_resources[std::type_index(typeid(T))] = std::shared_ptr<void>(value.release(), [](void* p) { delete static_cast<T*>(p); });
        return *raw;
    }
    /// The resource of type T, or null.
    template <class T> T* resource() {
        auto it = m_resources.find(std::type_index(typeid(T)));
        return it == m_resources.end() ? nullptr : static_cast<T*>(it->second.get());
    }

private:
    struct PoolSlot {
        std::shared_ptr<void> object;
        void (*remove)(void*, Entity) = nullptr;
    };
    uint32_t m_lastId = 0;
    std::unordered_map<std::type_index, PoolSlot> m_pools;
    std::unordered_map<std::type_index, std::shared_ptr<void>> m_resources;
};

} // namespace ob::ecs
