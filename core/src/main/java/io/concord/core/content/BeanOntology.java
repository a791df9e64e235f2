package io.concord.core.content;

import java.lang.reflect.Constructor;
import java.lang.reflect.ParameterizedType;
import java.lang.reflect.RecordComponent;
import java.lang.reflect.Type;
import java.time.Instant;
import java.util.ArrayList;
import java.util.Collection;
import java.util.Comparator;
import java.util.Date;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;

/**
 * An ontology built from Java records, as JADE's {@code BeanOntology} builds one from beans: each
 * record that implements {@link Concept}, {@link AgentAction} or {@link Predicate} gets a schema
 * named by its simple name (or {@link Element}), with one slot per component, named as the
 * component (or {@link Slot#name()}), in alphabetical order of slot names (JADE's order), an
 * aggregate for a {@link List} ({@code sequence}) or {@link Set} ({@code set}), mandatory when the
 * component's type is a Java primitive or {@link Slot#mandatory()} says so. Slot types: strings,
 * {@code int}/{@code long}, {@code float}/{@code double}, {@code boolean}, {@link Instant} or
 * {@link Date}, {@code byte[]}, {@link io.concord.core.acl.AID}, another element of the ontology,
 * or {@link Object} for any. It extends the {@link BasicOntology}.
 */
public final class BeanOntology implements Ontology {

    private final String name;
    private final Map<Class<?>, Bean> beans = new LinkedHashMap<>();
    private final Map<String, Schema> schemas = new LinkedHashMap<>();

    /**
     * An ontology of these records.
     *
     * @param name    the ontology's name, for the {@code :ontology} slot
     * @param records the element classes; each must be a record implementing {@link Concept},
     *                {@link AgentAction} or {@link Predicate}
     * @throws IllegalArgumentException naming the class and component that cannot be mapped
     */
    public BeanOntology(String name, Class<?>... records) {
        this.name = Objects.requireNonNull(name, "name");
        for (Class<?> c : records) {
            Bean b = bean(c);
            if (schemas.containsKey(b.schema().name()) || BasicOntology.INSTANCE.schema(b.schema().name()) != null) {
                throw new IllegalArgumentException("two schemas named " + b.schema().name());
            }
            beans.put(c, b);
            schemas.put(b.schema().name(), b.schema());
        }
    }

    @Override
    public String name() {
        return name;
    }

    @Override
    public Schema schema(String symbol) {
        Schema s = schemas.get(symbol);
        return s != null ? s : BasicOntology.INSTANCE.schema(symbol);
    }

    @Override
    public Collection<Schema> schemas() {
        return List.copyOf(schemas.values());
    }

    @Override
    public AbsObject toAbs(Object value) throws ContentException {
        return new Mapper(this, beans).toAbs(value);
    }

    @Override
    public Object fromAbs(AbsObject abs) throws ContentException {
        return new Mapper(this, beans).fromAbs(abs, Object.class, "content");
    }

    /** A record's schema, its components' accessors and its constructor. */
    record Bean(Schema schema, List<RecordComponent> components, Constructor<?> constructor, int[] argumentOf) {
        Object get(Object v, int slot) throws ContentException {
            try {
                return components.get(slot).getAccessor().invoke(v);
            } catch (ReflectiveOperationException e) {
                throw new ContentException("cannot read slot :" + schema.slots().get(slot).name() + " of " + schema.name(), e);
            }
        }

        Object create(Object[] slotValues) throws ContentException {
            Object[] args = new Object[slotValues.length];
            for (int i = 0; i < slotValues.length; i++) {
                Object v = slotValues[i];
                Class<?> t = components.get(i).getType();
                if (v == null && t.isPrimitive()) {
                    throw new ContentException("missing mandatory slot :" + schema.slots().get(i).name() + " of " + schema.name());
                }
                args[argumentOf[i]] = v;
            }
            return Mapper.invoke(constructor, args, schema.name());
        }
    }

    private static Bean bean(Class<?> c) {
        if (!c.isRecord()) {
            throw new IllegalArgumentException(c.getName() + " is not a record");
        }
        Schema.Kind kind;
        if (AgentAction.class.isAssignableFrom(c)) {
            kind = Schema.Kind.AGENT_ACTION;
        } else if (Predicate.class.isAssignableFrom(c)) {
            kind = Schema.Kind.PREDICATE;
        } else if (Concept.class.isAssignableFrom(c)) {
            kind = Schema.Kind.CONCEPT;
        } else {
            throw new IllegalArgumentException(c.getName() + " implements none of Concept, AgentAction, Predicate");
        }
        Element element = c.getAnnotation(Element.class);
        String schemaName = element != null ? element.name() : c.getSimpleName();
        RecordComponent[] declared = c.getRecordComponents();
        List<Integer> order = new ArrayList<>();
        List<Schema.SlotSchema> slots = new ArrayList<>();
        Map<Integer, Schema.SlotSchema> byIndex = new LinkedHashMap<>();
        for (int i = 0; i < declared.length; i++) {
            byIndex.put(i, slot(c, declared[i]));
            order.add(i);
        }
        order.sort(Comparator.comparing(i -> byIndex.get(i).name()));
        List<RecordComponent> components = new ArrayList<>();
        int[] argumentOf = new int[declared.length];
        for (int k = 0; k < order.size(); k++) {
            int i = order.get(k);
            slots.add(byIndex.get(i));
            components.add(declared[i]);
            argumentOf[k] = i;
        }
        Class<?>[] types = new Class<?>[declared.length];
        for (int i = 0; i < declared.length; i++) {
            types[i] = declared[i].getType();
        }
        try {
            Constructor<?> ctor = c.getDeclaredConstructor(types);
            ctor.setAccessible(true);
            return new Bean(new Schema(schemaName, kind, c, slots), components, ctor, argumentOf);
        } catch (ReflectiveOperationException | RuntimeException e) {
            throw new IllegalArgumentException(c.getName() + ": no accessible canonical constructor", e);
        }
    }

    private static Schema.SlotSchema slot(Class<?> owner, RecordComponent rc) {
        Slot a = rc.getAnnotation(Slot.class);
        String slotName = a != null && !a.name().isEmpty() ? a.name() : rc.getName();
        Class<?> type = rc.getType();
        String aggregate = null;
        if (List.class.isAssignableFrom(type) || Set.class.isAssignableFrom(type)) {
            aggregate = Set.class.isAssignableFrom(type) ? AbsAggregate.SET : AbsAggregate.SEQUENCE;
            type = elementType(owner, rc);
        } else if (Collection.class.isAssignableFrom(type)) {
            throw new IllegalArgumentException(owner.getName() + "." + rc.getName() + ": use a List or a Set");
        }
        if (!mappable(type)) {
            throw new IllegalArgumentException(owner.getName() + "." + rc.getName() + ": no SL type for " + type.getName());
        }
        boolean mandatory = rc.getType().isPrimitive() || (a != null && (a.mandatory() || a.cardMin() > 0));
        int cardMin = a != null ? a.cardMin() : 0;
        int cardMax = a != null ? a.cardMax() : -1;
        return new Schema.SlotSchema(slotName, type, aggregate, mandatory, cardMin, cardMax);
    }

    private static Class<?> elementType(Class<?> owner, RecordComponent rc) {
        Type t = rc.getGenericType();
        if (t instanceof ParameterizedType p && p.getActualTypeArguments()[0] instanceof Class<?> e) {
            return e;
        }
        throw new IllegalArgumentException(owner.getName() + "." + rc.getName() + ": an aggregate needs an element class");
    }

    private static boolean mappable(Class<?> t) {
        return t.isPrimitive() && t != char.class && t != short.class && t != byte.class && t != void.class
                || t == String.class || t == Long.class || t == Integer.class || t == Double.class || t == Float.class
                || t == Boolean.class || t == Instant.class || t == Date.class || t == byte[].class || t == Object.class
                || t == io.concord.core.acl.AID.class || t.isRecord() || t.isInterface();
    }
}
