package io.concord.core.content;

import java.lang.reflect.Constructor;
import java.lang.reflect.Method;
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
 * An ontology built from Java records or beans, as JADE's {@code BeanOntology} builds one from
 * beans: each record or bean (a public getter {@code getX}/{@code isX} and setter {@code setX} per
 * property, a no-argument constructor) that implements {@link Concept}, {@link AgentAction} or {@link Predicate} gets a schema
 * named by its simple name (or {@link Element}), with one slot per component or property, named
 * as it (or {@link Slot#name()}, on the component or the getter), in alphabetical order of slot names (JADE's order;
 * or by {@link Slot#position()}, and then written by position), an
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
     * @param records the element classes; each a record or bean implementing {@link Concept},
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

    /** One Java property: a record component, or a bean's getter and setter. */
    record Property(String name, Method getter, Method setter, Type genericType, Slot annotation) {
        Class<?> type() {
            return getter.getReturnType();
        }
    }

    /**
     * An element's schema, its properties in slot order, and how to build one: a record's
     * canonical constructor (argument {@code argumentOf[slot]}), or a bean's no-argument
     * constructor and setters.
     */
    record Bean(Schema schema, List<Property> properties, Constructor<?> constructor, int[] argumentOf, boolean record,
                boolean positional) {
        Object get(Object v, int slot) throws ContentException {
            try {
                return properties.get(slot).getter().invoke(v);
            } catch (ReflectiveOperationException e) {
                throw new ContentException("cannot read slot :" + schema.slots().get(slot).name() + " of " + schema.name()
                        + (e instanceof IllegalAccessException ? ": its class and accessor must be public"
                        : ": " + (e instanceof java.lang.reflect.InvocationTargetException ite ? ite.getCause() : e)), e);
            }
        }

        Object create(Object[] slotValues) throws ContentException {
            for (int i = 0; i < slotValues.length; i++) {
                if (slotValues[i] == null && properties.get(i).type().isPrimitive()) {
                    throw new ContentException("missing mandatory slot :" + schema.slots().get(i).name() + " of " + schema.name());
                }
            }
            if (record) {
                Object[] args = new Object[slotValues.length];
                for (int i = 0; i < slotValues.length; i++) {
                    args[argumentOf[i]] = slotValues[i];
                }
                return Mapper.invoke(constructor, args, schema.name());
            }
            Object bean = Mapper.invoke(constructor, new Object[0], schema.name());
            for (int i = 0; i < slotValues.length; i++) {
                if (slotValues[i] != null) {
                    try {
                        properties.get(i).setter().invoke(bean, slotValues[i]);
                    } catch (java.lang.reflect.InvocationTargetException e) {
                        throw new ContentException(schema.name() + " refused slot :" + schema.slots().get(i).name()
                                + ": " + e.getCause().getMessage(), e.getCause());
                    } catch (ReflectiveOperationException | IllegalArgumentException e) {
                        throw new ContentException("cannot set slot :" + schema.slots().get(i).name() + " of " + schema.name(), e);
                    }
                }
            }
            return bean;
        }
    }

    private static Bean bean(Class<?> c) {
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
        List<Property> declared = c.isRecord() ? recordProperties(c) : beanProperties(c);
        List<Integer> order = new ArrayList<>();
        Map<Integer, Schema.SlotSchema> byIndex = new LinkedHashMap<>();
        for (int i = 0; i < declared.size(); i++) {
            byIndex.put(i, slot(c, declared.get(i)));
            order.add(i);
        }
        boolean positional = declared.stream().anyMatch(p -> p.annotation() != null && p.annotation().position() >= 0);
        if (positional) {
            java.util.Set<Integer> places = new java.util.HashSet<>();
            for (Property p : declared) {
                int at = p.annotation() == null ? -1 : p.annotation().position();
                if (at < 0 || at >= declared.size() || !places.add(at)) {
                    throw new IllegalArgumentException(c.getName() + "." + p.name() + ": every slot of a positional element needs "
                            + "its own @Slot(position) from 0 to " + (declared.size() - 1));
                }
            }
            order.sort(Comparator.comparingInt(i -> declared.get(i).annotation().position()));
        } else {
            order.sort(Comparator.comparing(i -> byIndex.get(i).name()));
        }
        List<Schema.SlotSchema> slots = new ArrayList<>();
        List<Property> properties = new ArrayList<>();
        int[] argumentOf = new int[declared.size()];
        for (int k = 0; k < order.size(); k++) {
            int i = order.get(k);
            slots.add(byIndex.get(i));
            properties.add(declared.get(i));
            argumentOf[k] = i;
        }
        try {
            Constructor<?> ctor;
            if (c.isRecord()) {
                ctor = c.getDeclaredConstructor(declared.stream().map(Property::type).toArray(Class<?>[]::new));
            } else {
                ctor = c.getDeclaredConstructor();
            }
            ctor.setAccessible(true);
            return new Bean(new Schema(schemaName, kind, c, slots), properties, ctor, argumentOf, c.isRecord(), positional);
        } catch (ReflectiveOperationException | RuntimeException e) {
            throw new IllegalArgumentException(c.getName() + ": no accessible " + (c.isRecord() ? "canonical" : "no-argument")
                    + " constructor", e);
        }
    }

    private static List<Property> recordProperties(Class<?> c) {
        List<Property> out = new ArrayList<>();
        for (RecordComponent rc : c.getRecordComponents()) {
            out.add(new Property(rc.getName(), rc.getAccessor(), null, rc.getGenericType(), rc.getAnnotation(Slot.class)));
        }
        return out;
    }

    /** A bean's properties, as JADE finds them ({@link BeanAccessors}). */
    private static List<Property> beanProperties(Class<?> c) {
        List<Property> out = new ArrayList<>();
        for (BeanAccessors.Accessor a : BeanAccessors.of(c)) {
            out.add(new Property(a.name(), a.getter(), a.setter(), a.getter().getGenericReturnType(), a.getter().getAnnotation(Slot.class)));
        }
        return out;
    }

    private static Schema.SlotSchema slot(Class<?> owner, Property p) {
        Slot a = p.annotation();
        String slotName = a != null && !a.name().isEmpty() ? a.name() : p.name();
        Class<?> type = p.type();
        String aggregate = null;
        if (List.class.isAssignableFrom(type) || Set.class.isAssignableFrom(type)) {
            aggregate = Set.class.isAssignableFrom(type) ? AbsAggregate.SET : AbsAggregate.SEQUENCE;
            type = elementType(owner, p);
        } else if (Collection.class.isAssignableFrom(type)) {
            throw new IllegalArgumentException(owner.getName() + "." + p.name() + ": use a List or a Set");
        }
        if (!mappable(type)) {
            throw new IllegalArgumentException(owner.getName() + "." + p.name() + ": no SL type for " + type.getName());
        }
        boolean mandatory = p.type().isPrimitive() || (a != null && (a.mandatory() || a.cardMin() > 0));
        int cardMin = a != null ? a.cardMin() : 0;
        int cardMax = a != null ? a.cardMax() : -1;
        return new Schema.SlotSchema(slotName, type, aggregate, mandatory, cardMin, cardMax);
    }

    private static Class<?> elementType(Class<?> owner, Property p) {
        if (p.genericType() instanceof ParameterizedType t && t.getActualTypeArguments()[0] instanceof Class<?> e) {
            return e;
        }
        throw new IllegalArgumentException(owner.getName() + "." + p.name() + ": an aggregate needs an element class");
    }

    private static boolean mappable(Class<?> t) {
        return t.isPrimitive() && t != char.class && t != short.class && t != byte.class && t != void.class
                || t == String.class || t == Long.class || t == Integer.class || t == Double.class || t == Float.class
                || t == Boolean.class || t == Instant.class || t == Date.class || t == byte[].class || t == Object.class
                || t == io.concord.core.acl.AID.class || t.isRecord() || t.isInterface()
                || Concept.class.isAssignableFrom(t) || Predicate.class.isAssignableFrom(t);
    }
}
