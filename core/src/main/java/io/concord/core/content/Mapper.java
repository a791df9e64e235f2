package io.concord.core.content;

import io.concord.core.acl.AID;

import java.lang.reflect.InvocationTargetException;
import java.time.Instant;
import java.util.ArrayList;
import java.util.Collection;
import java.util.Date;
import java.util.List;
import java.util.Map;
import java.util.Set;

/** Maps Java objects to abstract content and back for one ontology, checking the facets. */
final class Mapper {
    private final Ontology ontology;
    private final Map<Class<?>, BeanOntology.Bean> beans;

    Mapper(Ontology ontology, Map<Class<?>, BeanOntology.Bean> beans) {
        this.ontology = ontology;
        this.beans = beans;
    }

    AbsObject toAbs(Object v) throws ContentException {
        if (v == null) {
            throw new ContentException("null has no abstract form");
        }
        if (v instanceof AbsObject abs) {
            return abs;
        }
        AbsObject basic = BasicOntology.basicToAbs(v, this);
        if (basic != null) {
            return basic;
        }
        BeanOntology.Bean bean = beans.get(v.getClass());
        if (bean == null) {
            throw new ContentException("no schema in ontology " + ontology.name() + " for " + v.getClass().getName());
        }
        Schema schema = bean.schema();
        boolean positional = schema.kind() == Schema.Kind.PREDICATE || bean.positional();
        List<AbsCompound.Slot> slots = new ArrayList<>();
        for (int i = 0; i < schema.slots().size(); i++) {
            Schema.SlotSchema s = schema.slots().get(i);
            Object value = bean.get(v, i);
            if (value instanceof Collection<?> c && c.isEmpty() && !s.mandatory() && !positional && s.cardMin() == 0) {
                // JADE leaves an empty aggregate out; it reads back as an absent slot
                continue;
            }
            if (value == null) {
                if (s.mandatory() || positional) {
                    throw new ContentException("missing mandatory slot :" + s.name() + " of " + schema.name());
                }
                continue;
            }
            AbsObject abs;
            if (s.aggregate() != null) {
                Collection<?> c = (Collection<?>) value;
                cardinality(schema, s, c.size());
                abs = new AbsAggregate(s.aggregate(), toAbsAll(c));
            } else {
                abs = toAbs(value);
            }
            slots.add(new AbsCompound.Slot(positional ? null : s.name(), abs));
        }
        return new AbsCompound(schema.name(), slots);
    }

    List<AbsObject> toAbsAll(Collection<?> c) throws ContentException {
        List<AbsObject> out = new ArrayList<>(c.size());
        for (Object o : c) {
            out.add(toAbs(o));
        }
        return out;
    }

    private static void cardinality(Schema schema, Schema.SlotSchema s, int n) throws ContentException {
        if (n < s.cardMin() || (s.cardMax() >= 0 && n > s.cardMax())) {
            throw new ContentException("slot :" + s.name() + " of " + schema.name() + " has " + n
                    + " element(s), allowed " + s.cardMin() + ".." + (s.cardMax() < 0 ? "*" : s.cardMax()));
        }
    }

    Object fromAbs(AbsObject o, Class<?> expected, String where) throws ContentException {
        if (o instanceof AbsVariable v) {
            throw new ContentException(where + ": variable ?" + v.name() + " where a value is needed");
        }
        if (o instanceof AbsPrimitive p) {
            return primitive(p.value(), expected, where);
        }
        if (o instanceof AbsAggregate a) {
            if (expected != Object.class && !Collection.class.isAssignableFrom(expected)) {
                throw new ContentException(where + ": expected " + typeName(expected) + ", got " + a.type());
            }
            List<Object> elements = new ArrayList<>();
            for (AbsObject e : a.elements()) {
                elements.add(fromAbs(e, Object.class, where));
            }
            return a.type().equals(AbsAggregate.SET) ? BasicOntology.newSet(elements) : elements;
        }
        AbsCompound c = (AbsCompound) o;
        Object value = BasicOntology.basicFromAbs(c, this);
        if (value == null) {
            BeanOntology.Bean bean = beanNamed(c.name());
            if (bean == null) {
                throw new ContentException(where + ": no schema in ontology " + ontology.name() + " for symbol " + c.name());
            }
            value = bean(c, bean);
        }
        if (!expected.isInstance(value) && expected != Object.class) {
            throw new ContentException(where + ": expected " + typeName(expected) + ", got " + c.name());
        }
        return value;
    }

    private BeanOntology.Bean beanNamed(String name) {
        for (BeanOntology.Bean b : beans.values()) {
            if (b.schema().name().equals(name)) {
                return b;
            }
        }
        return null;
    }

    private Object bean(AbsCompound c, BeanOntology.Bean bean) throws ContentException {
        Schema schema = bean.schema();
        if (!c.isNamed() && c.slots().size() > schema.slots().size()) {
            throw new ContentException(schema.name() + " takes at most " + schema.slots().size()
                    + " argument(s), got " + c.slots().size());
        }
        if (c.isNamed()) {
            for (AbsCompound.Slot s : c.slots()) {
                if (schema.slot(s.name()) == null) {
                    throw new ContentException("unknown slot :" + s.name() + " of " + schema.name());
                }
            }
        }
        Object[] args = new Object[schema.slots().size()];
        for (int i = 0; i < args.length; i++) {
            Schema.SlotSchema s = schema.slots().get(i);
            Object v = slot(c, i, s.name(), s.type(), s.aggregate());
            if (v == null && s.mandatory()) {
                throw new ContentException("missing mandatory slot :" + s.name() + " of " + schema.name());
            }
            if (v != null && s.aggregate() != null) {
                cardinality(schema, s, ((Collection<?>) v).size());
                if (s.aggregate().equals(AbsAggregate.SET) != (v instanceof Set)) {
                    throw new ContentException("slot :" + s.name() + " of " + schema.name() + " must be a " + s.aggregate());
                }
            }
            args[i] = v;
        }
        return bean.create(args);
    }

    /** The slot's value by name (or by position when the compound is positional), or null when absent. */
    Object slot(AbsCompound c, int index, String name, Class<?> type, String aggregate) throws ContentException {
        AbsObject abs;
        if (c.isNamed()) {
            abs = c.get(name);
        } else {
            abs = index < c.slots().size() ? c.slots().get(index).value() : null;
        }
        if (abs == null) {
            return null;
        }
        String where = "slot :" + name + " of " + c.name();
        if (aggregate == null) {
            return fromAbs(abs, type, where);
        }
        if (!(abs instanceof AbsAggregate a) || !a.type().equals(aggregate)) {
            throw new ContentException("slot :" + name + " of " + c.name() + " must be a " + aggregate);
        }
        List<Object> elements = new ArrayList<>();
        for (AbsObject e : a.elements()) {
            elements.add(fromAbs(e, type, where));
        }
        return a.type().equals(AbsAggregate.SET) ? BasicOntology.newSet(elements) : elements;
    }

    Object positional(AbsCompound c, int index, Class<?> type) throws ContentException {
        arity(c, c.name().equals("action") || c.name().equals("result") || c.name().equals("=") ? 2 : 1);
        if (c.isNamed()) {
            throw new ContentException(c.name() + " takes positional arguments");
        }
        return fromAbs(c.slots().get(index).value(), type, "argument " + (index + 1) + " of " + c.name());
    }

    void arity(AbsCompound c, int n) throws ContentException {
        if (c.slots().size() != n) {
            throw new ContentException(c.name() + " takes " + n + " argument(s), got " + c.slots().size());
        }
    }

    void noOtherSlots(AbsCompound c, Set<String> names) throws ContentException {
        for (AbsCompound.Slot s : c.slots()) {
            if (s.name() != null && !names.contains(s.name())) {
                throw new ContentException("unknown slot :" + s.name() + " of " + c.name());
            }
        }
    }

    private static Object primitive(Object v, Class<?> expected, String where) throws ContentException {
        if (expected == Object.class) {
            return v;
        }
        if (v instanceof Boolean b && (expected == Predicate.class || expected == TrueProposition.class
                || expected == FalseProposition.class)) {
            Object proposition = b ? new TrueProposition() : new FalseProposition();
            if (expected.isInstance(proposition)) {
                return proposition;
            }
        }
        Class<?> e = box(expected);
        if (e == Long.class && (v instanceof Long || v instanceof Integer)) {
            return ((Number) v).longValue();
        }
        if (e == Integer.class && (v instanceof Long || v instanceof Integer)) {
            long l = ((Number) v).longValue();
            if (l < Integer.MIN_VALUE || l > Integer.MAX_VALUE) {
                throw new ContentException(where + ": " + l + " is out of the range of an int");
            }
            return (int) l;
        }
        if (e == Double.class && v instanceof Number n) {
            return n.doubleValue();
        }
        if (e == Float.class && v instanceof Number n) {
            return n.floatValue();
        }
        if (e == Date.class && v instanceof Instant t) {
            return Date.from(t);
        }
        if (e.isInstance(v)) {
            return v;
        }
        throw new ContentException(where + ": expected " + typeName(expected) + ", got " + typeName(v.getClass()));
    }

    static Class<?> box(Class<?> c) {
        if (!c.isPrimitive()) {
            return c;
        }
        if (c == int.class) {
            return Integer.class;
        }
        if (c == long.class) {
            return Long.class;
        }
        if (c == double.class) {
            return Double.class;
        }
        if (c == float.class) {
            return Float.class;
        }
        if (c == boolean.class) {
            return Boolean.class;
        }
        return c;
    }

    static String typeName(Class<?> c) {
        Class<?> b = box(c);
        if (b == String.class) {
            return "string";
        }
        if (b == Long.class || b == Integer.class) {
            return "integer";
        }
        if (b == Double.class || b == Float.class) {
            return "float";
        }
        if (b == Boolean.class) {
            return "boolean";
        }
        if (b == Instant.class || b == Date.class) {
            return "date";
        }
        if (b == byte[].class) {
            return "byte-sequence";
        }
        if (b == AID.class) {
            return "agent-identifier";
        }
        return c.getSimpleName();
    }

    static Object invoke(java.lang.reflect.Constructor<?> ctor, Object[] args, String name) throws ContentException {
        try {
            return ctor.newInstance(args);
        } catch (InvocationTargetException e) {
            throw new ContentException(name + " refused its slots: " + e.getCause().getMessage(), e.getCause());
        } catch (ReflectiveOperationException | IllegalArgumentException e) {
            throw new ContentException(name + " could not be built: " + e.getMessage(), e);
        }
    }
}
