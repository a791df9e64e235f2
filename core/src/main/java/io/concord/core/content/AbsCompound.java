package io.concord.core.content;

import java.util.List;
import java.util.Objects;

/**
 * A compound: a functional term, concept, predicate, action or operator applied to arguments,
 * written {@code (name :slot value ...)} when its slots are named and {@code (name value ...)}
 * when they are positional. A compound has either only named or only positional slots.
 *
 * @param name  its symbol, such as {@code Book}, {@code action}, {@code and}, {@code iota}
 * @param slots its slots, in the order they are written
 */
public record AbsCompound(String name, List<Slot> slots) implements AbsObject {

    /**
     * One argument of a compound.
     *
     * @param name  the slot's name without the colon, or null for a positional argument
     * @param value its value
     */
    public record Slot(String name, AbsObject value) {
        /** Checks the value is present. */
        public Slot {
            Objects.requireNonNull(value, "value");
        }
    }

    /** Copies the slots and checks they are all named or all positional. */
    public AbsCompound {
        Objects.requireNonNull(name, "name");
        slots = List.copyOf(slots);
        long named = slots.stream().filter(s -> s.name() != null).count();
        if (named != 0 && named != slots.size()) {
            throw new IllegalArgumentException(name + ": slots must be all named or all positional");
        }
    }

    /** A compound with positional arguments. */
    public static AbsCompound positional(String name, AbsObject... args) {
        return new AbsCompound(name, java.util.Arrays.stream(args).map(a -> new Slot(null, a)).toList());
    }

    /** True if its slots are written by name. */
    public boolean isNamed() {
        return !slots.isEmpty() && slots.get(0).name() != null;
    }

    /** The value of the named slot, or null when absent. */
    public AbsObject get(String slotName) {
        for (Slot s : slots) {
            if (slotName.equals(s.name())) {
                return s.value();
            }
        }
        return null;
    }
}
