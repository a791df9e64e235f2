package jade.content.schema;

import io.concord.jadecompat.internal.SlotFacets;
import jade.content.onto.OntologyException;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The schema of a kind of content, as JADE's: a type name and slots, each with a schema, an
 * optionality and, for an aggregate slot, a cardinality. Slots keep the order they were added in
 * (a super-schema's slots first): a predicate, and an element whose schema is encoded by order, is
 * written with its slots by position in that order; concepts and actions by name.
 */
public abstract class ObjectSchema implements jade.util.leap.Serializable, SlotFacets {
    private static final long serialVersionUID = 1L;
    /** A slot that must have a value. */
    public static final int MANDATORY = 0;
    /** A slot that may be absent. */
    public static final int OPTIONAL = 1;
    /** No upper limit to an aggregate's cardinality. */
    public static final int UNLIMITED = -1;
    /** The name of the schema every schema descends from. */
    public static final String BASE_NAME = "Object";
    private static final ObjectSchema BASE = new ObjectSchema() {
        private static final long serialVersionUID = 1L;
    };

    /** The schema every schema descends from (a slot of this schema takes any value). */
    public static ObjectSchema getBaseSchema() {
        return BASE;
    }

    /** Whether the element is written by position rather than by slot name. */
    protected boolean encodingByOrder;

    private final String typeName;
    private final Map<String, SlotDef> slots = new LinkedHashMap<>();
    private final List<ObjectSchema> superSchemas = new ArrayList<>();

    private record SlotDef(ObjectSchema schema, boolean mandatory, int cardMin, int cardMax) implements java.io.Serializable {
    }

    /** The base schema. */
    public ObjectSchema() {
        this(BASE_NAME);
    }

    ObjectSchema(String typeName) {
        this.typeName = typeName;
    }

    /** Adds a slot with that optionality ({@link #MANDATORY} or {@link #OPTIONAL}). */
    protected void add(String name, ObjectSchema slotSchema, int optionality) {
        put(name, slotSchema, optionality == MANDATORY, 0, UNLIMITED);
    }

    /** Adds a mandatory slot. */
    protected void add(String name, ObjectSchema slotSchema) {
        add(name, slotSchema, MANDATORY);
    }

    /** Adds an aggregate slot ({@code sequence}) of elements of that schema, mandatory when cardMin is above 0. */
    protected void add(String name, ObjectSchema elementsSchema, int cardMin, int cardMax) {
        add(name, elementsSchema, cardMin, cardMax, "sequence");
    }

    /** Adds an aggregate slot of that aggregate type ({@code sequence} or {@code set}). */
    protected void add(String name, ObjectSchema elementsSchema, int cardMin, int cardMax, String aggregateType) {
        add(name, elementsSchema, cardMin, cardMax, aggregateType, cardMin > 0 ? MANDATORY : OPTIONAL);
    }

    /** Adds an aggregate slot of that aggregate type and optionality. */
    protected void add(String name, ObjectSchema elementsSchema, int cardMin, int cardMax, String aggregateType, int optionality) {
        if (!"sequence".equals(aggregateType) && !"set".equals(aggregateType)) {
            throw new IllegalArgumentException("aggregate type must be sequence or set: " + aggregateType);
        }
        AggregateSchema aggregate = new AggregateSchema(aggregateType, (TermSchema) elementsSchema);
        put(name, aggregate, optionality == MANDATORY, cardMin, cardMax);
    }

    private void put(String name, ObjectSchema slotSchema, boolean mandatory, int cardMin, int cardMax) {
        if (name == null || slotSchema == null) {
            throw new IllegalArgumentException("a slot needs a name and a schema");
        }
        if (cardMin < 0 || (cardMax >= 0 && cardMax < cardMin)) {
            throw new IllegalArgumentException(name + ": bad cardinality " + cardMin + ".." + cardMax);
        }
        slots.put(name, new SlotDef(slotSchema, mandatory, cardMin, cardMax));
    }

    /** Makes this schema inherit the slots of that one. */
    protected void addSuperSchema(ObjectSchema superSchema) {
        superSchemas.add(superSchema);
    }

    /** Writes the element by position (in slot order) rather than by slot name. */
    public void setEncodingByOrder(boolean byOrder) {
        this.encodingByOrder = byOrder;
    }

    /** Whether the element is written by position. */
    public boolean getEncodingByOrder() {
        return encodingByOrder;
    }

    /** The schema's name, as written in the content. */
    public String getTypeName() {
        return typeName;
    }

    /** All slot names, the super-schemas' first. */
    public String[] getNames() {
        List<String> names = new ArrayList<>();
        for (ObjectSchema s : superSchemas) {
            for (String n : s.getNames()) {
                if (!names.contains(n)) {
                    names.add(n);
                }
            }
        }
        for (String n : slots.keySet()) {
            if (!names.contains(n)) {
                names.add(n);
            }
        }
        return names.toArray(new String[0]);
    }

    /** This schema's own slot names. */
    public String[] getOwnNames() {
        return slots.keySet().toArray(new String[0]);
    }

    private SlotDef def(String name) {
        SlotDef d = slots.get(name);
        if (d != null) {
            return d;
        }
        for (ObjectSchema s : superSchemas) {
            d = s.def(name);
            if (d != null) {
                return d;
            }
        }
        return null;
    }

    private SlotDef required(String name) throws OntologyException {
        SlotDef d = def(name);
        if (d == null) {
            throw new OntologyException("No slot named " + name + " in schema " + typeName);
        }
        return d;
    }

    /** The schema of that slot (an {@link AggregateSchema} for an aggregate slot). */
    public ObjectSchema getSchema(String name) throws OntologyException {
        return required(name).schema();
    }

    /** Whether the schema (or a super-schema) has that slot. */
    public boolean containsSlot(String name) {
        return def(name) != null;
    }

    /** Whether this schema itself defines that slot. */
    public boolean isOwnSlot(String name) {
        return slots.containsKey(name);
    }

    /** Whether that slot must have a value. */
    public boolean isMandatory(String name) throws OntologyException {
        return required(name).mandatory();
    }

    /** The super-schemas. */
    public ObjectSchema[] getSuperSchemas() {
        return superSchemas.toArray(new ObjectSchema[0]);
    }

    /** Whether this schema is that one or descends from it. */
    public boolean isAssignableFrom(ObjectSchema other) {
        if (other == null) {
            return false;
        }
        if (other == this || other.getTypeName().equals(typeName) && other.getClass() == getClass()) {
            return true;
        }
        for (ObjectSchema s : other.superSchemas) {
            if (isAssignableFrom(s)) {
                return true;
            }
        }
        return false;
    }

    @Override
    public int cardMin(String slot) {
        SlotDef d = def(slot);
        return d == null ? 0 : d.cardMin();
    }

    @Override
    public int cardMax(String slot) {
        SlotDef d = def(slot);
        return d == null ? UNLIMITED : d.cardMax();
    }

    @Override
    public String toString() {
        return getClass().getSimpleName() + "-" + typeName;
    }
}
