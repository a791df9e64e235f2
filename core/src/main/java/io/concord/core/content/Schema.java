package io.concord.core.content;

import java.util.List;
import java.util.Objects;

/**
 * The schema of one kind of content: its name, its kind and its slots with their facets.
 *
 * @param name      the symbol written in the content, such as {@code Book}
 * @param kind      concept, predicate, agent action, aggregate or primitive
 * @param javaClass the class its values map to
 * @param slots     the slots, in the order they are written
 */
public record Schema(String name, Kind kind, Class<?> javaClass, List<SlotSchema> slots) {

    /** What a schema describes. */
    public enum Kind {
        /** A thing, written with named slots. */
        CONCEPT,
        /** An action an agent does, written with named slots. */
        AGENT_ACTION,
        /** A proposition, written with positional slots. */
        PREDICATE,
        /** A sequence or a set. */
        AGGREGATE,
        /** A string, number, boolean, date or byte string. */
        PRIMITIVE
    }

    /**
     * One slot and its facets.
     *
     * @param name        the slot's name
     * @param type        the class of its value, or of each element of an aggregate
     * @param aggregate   {@code sequence} or {@code set} for an aggregate slot, else null
     * @param mandatory   whether a value must be present
     * @param cardMin     an aggregate's fewest elements
     * @param cardMax     an aggregate's most elements, -1 for no limit
     */
    public record SlotSchema(String name, Class<?> type, String aggregate, boolean mandatory, int cardMin, int cardMax) {
        /** Checks the facets agree. */
        public SlotSchema {
            Objects.requireNonNull(name, "name");
            Objects.requireNonNull(type, "type");
            if (cardMin < 0 || (cardMax >= 0 && cardMax < cardMin)) {
                throw new IllegalArgumentException(name + ": bad cardinality " + cardMin + ".." + cardMax);
            }
        }
    }

    /** Copies the slots. */
    public Schema {
        Objects.requireNonNull(name, "name");
        Objects.requireNonNull(kind, "kind");
        slots = List.copyOf(slots);
    }

    /** The slot of that name, or null. */
    public SlotSchema slot(String slotName) {
        for (SlotSchema s : slots) {
            if (s.name().equals(slotName)) {
                return s;
            }
        }
        return null;
    }
}
