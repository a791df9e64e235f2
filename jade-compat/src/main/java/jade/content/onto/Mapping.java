package jade.content.onto;

import io.concord.core.content.AbsAggregate;
import io.concord.core.content.AbsCompound;
import io.concord.core.content.AbsObject;
import io.concord.core.content.AbsPrimitive;
import io.concord.core.content.AbsVariable;
import jade.content.Concept;
import jade.content.Predicate;
import jade.content.onto.basic.Action;
import jade.content.onto.basic.Done;
import jade.content.onto.basic.Equals;
import jade.content.onto.basic.FalseProposition;
import jade.content.onto.basic.Result;
import jade.content.onto.basic.TrueProposition;
import jade.content.schema.AggregateSchema;
import jade.content.schema.ConceptSchema;
import jade.content.schema.ObjectSchema;
import jade.content.schema.PredicateSchema;
import jade.content.schema.PrimitiveSchema;
import jade.core.AID;

import java.lang.reflect.Constructor;
import java.lang.reflect.InvocationTargetException;
import java.time.Instant;
import java.util.ArrayList;
import java.util.Collection;
import java.util.Date;
import java.util.LinkedHashSet;
import java.util.List;

/**
 * Java objects to Concord's abstract content and back, through a JADE-named ontology's schemas:
 * concepts and actions with named slots, predicates (and schemas encoded by order) by position,
 * in the schema's slot order; an empty aggregate in an optional slot is left out, as JADE does.
 */
final class Mapping {
    private final Ontology onto;
    private final boolean validate;

    Mapping(Ontology onto, boolean validate) {
        this.onto = onto;
        this.validate = validate;
    }

    // ---------------------------------------------------------------- Java -> abstract

    AbsObject toAbs(Object v) throws OntologyException {
        return term(v, null, "content");
    }

    private AbsObject term(Object v, String aggregateType, String where) throws OntologyException {
        if (v == null) {
            throw new OntologyException(where + ": null has no abstract form");
        }
        if (v instanceof String || v instanceof Boolean || v instanceof Long || v instanceof Integer
                || v instanceof Double || v instanceof Float || v instanceof byte[]) {
            return new AbsPrimitive(v);
        }
        if (v instanceof Short || v instanceof Byte) {
            return new AbsPrimitive(((Number) v).longValue());
        }
        if (v instanceof Date d) {
            return new AbsPrimitive(d.toInstant());
        }
        if (v instanceof AID aid) {
            return aid(aid);
        }
        if (v instanceof Action a) {
            return AbsCompound.positional("action", aid((AID) required(a.getActor(), "actor", "action")),
                    term(required(a.getAction(), "action", "action"), null, "argument 2 of action"));
        }
        if (v instanceof Done d) {
            return AbsCompound.positional("done", term(required(d.getAction(), "action", "done"), null, "argument 1 of done"));
        }
        if (v instanceof Result r) {
            return AbsCompound.positional("result", term(required(r.getAction(), "action", "result"), null, "argument 1 of result"),
                    term(required(r.getValue(), "value", "result"), null, "argument 2 of result"));
        }
        if (v instanceof Equals e) {
            return AbsCompound.positional("=", term(required(e.getLeft(), "left", "="), null, "argument 1 of ="),
                    term(required(e.getRight(), "right", "="), null, "argument 2 of ="));
        }
        if (v instanceof TrueProposition) {
            return new AbsPrimitive(Boolean.TRUE);
        }
        if (v instanceof FalseProposition) {
            return new AbsPrimitive(Boolean.FALSE);
        }
        if (v instanceof Enum<?> e) {
            ObjectSchema schema = schemaOf(e.getDeclaringClass());
            if (schema == null) {
                throw new OntologyException("no schema in ontology " + onto.getName() + " for enum " + e.getDeclaringClass().getName());
            }
            return new AbsCompound(schema.getTypeName(), List.of(new AbsCompound.Slot(BeanOntology.ENUM_NAME, new AbsPrimitive(e.name()))));
        }
        List<Object> elements = elements(v);
        if (elements != null) {
            String type = aggregateType != null ? aggregateType
                    : (v instanceof jade.util.leap.Set || v instanceof java.util.Set) ? AbsAggregate.SET : AbsAggregate.SEQUENCE;
            List<AbsObject> out = new ArrayList<>(elements.size());
            for (Object o : elements) {
                out.add(term(o, null, where));
            }
            return new AbsAggregate(type, out);
        }
        ObjectSchema schema = schemaOf(v.getClass());
        if (schema == null) {
            throw new OntologyException("no schema in ontology " + onto.getName() + " for class " + v.getClass().getName());
        }
        return compound(v, schema);
    }

    private static Object required(Object v, String slot, String of) throws OntologyException {
        if (v == null) {
            throw new OntologyException("missing mandatory slot :" + slot + " of " + of);
        }
        return v;
    }

    /** {@code sequence} or {@code set}, or null for the base aggregate schema (either). */
    private static String aggregateType(AggregateSchema s) {
        String t = s.getTypeName();
        return AbsAggregate.SEQUENCE.equals(t) || AbsAggregate.SET.equals(t) ? t : null;
    }

    private static boolean isBase(ObjectSchema s) {
        return s == ConceptSchema.getBaseSchema() || s == jade.content.schema.AgentActionSchema.getBaseSchema()
                || s.getTypeName().equals(jade.content.schema.TermSchema.BASE_NAME);
    }

    private static List<Object> elements(Object v) {
        List<Object> out = new ArrayList<>();
        if (v instanceof jade.util.leap.Collection c) {
            for (java.util.Iterator<?> it = c.iterator(); it.hasNext(); ) {
                out.add(it.next());
            }
            return out;
        }
        if (v instanceof Collection<?> c) {
            out.addAll(c);
            return out;
        }
        if (v.getClass().isArray() && !(v instanceof byte[])) {
            for (int i = 0; i < java.lang.reflect.Array.getLength(v); i++) {
                out.add(java.lang.reflect.Array.get(v, i));
            }
            return out;
        }
        return null;
    }

    private AbsCompound aid(AID aid) throws OntologyException {
        if (aid.getName() == null) {
            throw new OntologyException("missing mandatory slot :name of agent-identifier");
        }
        List<AbsCompound.Slot> slots = new ArrayList<>();
        slots.add(new AbsCompound.Slot("name", new AbsPrimitive(aid.getName())));
        String[] addresses = aid.getAddressesArray();
        if (addresses.length > 0) {
            List<AbsObject> a = new ArrayList<>();
            for (String s : addresses) {
                a.add(new AbsPrimitive(s));
            }
            slots.add(new AbsCompound.Slot("addresses", new AbsAggregate(AbsAggregate.SEQUENCE, a)));
        }
        AID[] resolvers = aid.getResolversArray();
        if (resolvers.length > 0) {
            List<AbsObject> r = new ArrayList<>();
            for (AID x : resolvers) {
                r.add(aid(x));
            }
            slots.add(new AbsCompound.Slot("resolvers", new AbsAggregate(AbsAggregate.SEQUENCE, r)));
        }
        return new AbsCompound("agent-identifier", slots);
    }

    private ObjectSchema schemaOf(Class<?> c) throws OntologyException {
        for (Class<?> k = c; k != null && k != Object.class; k = k.getSuperclass()) {
            ObjectSchema s = onto.getSchema(k);
            if (s != null) {
                return s;
            }
        }
        return null;
    }

    private AbsCompound compound(Object v, ObjectSchema schema) throws OntologyException {
        boolean positional = schema instanceof PredicateSchema || schema.getEncodingByOrder();
        String name = schema.getTypeName();
        List<AbsCompound.Slot> slots = new ArrayList<>();
        String leftOut = null;
        for (String slot : schema.getNames()) {
            Object value = get(onto.property(v.getClass(), slot), v, slot, name);
            ObjectSchema slotSchema = schema.getSchema(slot);
            boolean mandatory = schema.isMandatory(slot);
            String where = "slot :" + slot + " of " + name;
            if (slotSchema instanceof AggregateSchema) {
                List<Object> elements = value == null ? null : elements(value);
                if (value != null && elements == null) {
                    throw new OntologyException(where + ": expected a " + slotSchema.getTypeName() + ", got "
                            + value.getClass().getSimpleName());
                }
                if (elements != null && elements.isEmpty() && !mandatory && !positional) {
                    continue; // JADE leaves an empty aggregate out
                }
                if (elements != null) {
                    cardinality(schema, slot, elements.size());
                }
            }
            if (value == null) {
                if (mandatory) {
                    throw new OntologyException("missing mandatory slot :" + slot + " of " + name);
                }
                leftOut = slot;
                continue;
            }
            if (positional && leftOut != null) {
                throw new OntologyException(where + ": " + name + " is written by position and its slot :" + leftOut
                        + " before this one is empty");
            }
            AbsObject abs = term(value, slotSchema instanceof AggregateSchema a ? aggregateType(a) : null, where);
            if (abs instanceof AbsPrimitive p && slotSchema instanceof PrimitiveSchema ps) {
                checkPrimitive(ps, p.value(), where);
            }
            slots.add(new AbsCompound.Slot(positional ? null : slot, abs));
        }
        return new AbsCompound(name, slots);
    }

    private void cardinality(ObjectSchema schema, String slot, int n) throws OntologyException {
        int min = schema.cardMin(slot);
        int max = schema.cardMax(slot);
        if (n < min || (max >= 0 && n > max)) {
            throw new OntologyException("slot :" + slot + " of " + schema.getTypeName() + " has " + n
                    + " element(s), allowed " + min + ".." + (max < 0 ? "*" : max));
        }
    }

    private static Object get(Ontology.Property p, Object v, String slot, String name) throws OntologyException {
        try {
            return p.get(v);
        } catch (InvocationTargetException e) {
            throw new OntologyException("reading slot :" + slot + " of " + name + " failed: " + e.getCause(), e.getCause());
        } catch (ReflectiveOperationException e) {
            throw new OntologyException("reading slot :" + slot + " of " + name + " failed: " + e, e);
        }
    }

    private static void checkPrimitive(PrimitiveSchema schema, Object v, String where) throws OntologyException {
        String t = schema.getTypeName();
        boolean ok = switch (t) {
            case BasicOntology.STRING -> v instanceof String;
            case BasicOntology.INTEGER -> v instanceof Long || v instanceof Integer;
            case BasicOntology.FLOAT -> v instanceof Number;
            case BasicOntology.BOOLEAN -> v instanceof Boolean;
            case BasicOntology.DATE -> v instanceof Instant;
            case BasicOntology.BYTE_SEQUENCE -> v instanceof byte[];
            default -> true;
        };
        if (!ok) {
            throw new OntologyException(where + ": expected " + t + ", got " + kind(v));
        }
    }

    private static String kind(Object v) {
        if (v instanceof String) {
            return "a string";
        }
        if (v instanceof Long || v instanceof Integer) {
            return "an integer";
        }
        if (v instanceof Number) {
            return "a float";
        }
        if (v instanceof Boolean) {
            return "a boolean";
        }
        if (v instanceof Instant) {
            return "a date";
        }
        return "a byte sequence";
    }

    // ---------------------------------------------------------------- abstract -> Java

    Object fromAbs(AbsObject abs) throws OntologyException {
        if (abs instanceof AbsPrimitive p && p.value() instanceof Boolean b) {
            return b ? new TrueProposition() : new FalseProposition(); // SL's bare true and false as content
        }
        return value(abs, Object.class, null, null, "content");
    }

    private Object value(AbsObject abs, Class<?> expected, Class<?> elementType, ObjectSchema schema, String where)
            throws OntologyException {
        if (abs instanceof AbsVariable) {
            throw new UngroundedException();
        }
        if (abs instanceof AbsPrimitive p) {
            if (validate && schema instanceof PrimitiveSchema ps) {
                checkPrimitive(ps, p.value(), where);
            }
            return primitive(p.value(), expected, where);
        }
        if (abs instanceof AbsAggregate a) {
            return aggregate(a, expected, elementType, schema, where);
        }
        AbsCompound c = (AbsCompound) abs;
        Object value = basic(c, where);
        if (value == null) {
            value = bean(c, where);
        }
        if (!box(expected).isInstance(value)) {
            throw new OntologyException(where + ": expected " + expected.getSimpleName() + ", got " + c.name());
        }
        return value;
    }

    private Object aggregate(AbsAggregate a, Class<?> expected, Class<?> elementType, ObjectSchema schema, String where)
            throws OntologyException {
        if (validate && schema instanceof AggregateSchema s && aggregateType(s) != null && !s.getTypeName().equals(a.type())) {
            throw new OntologyException(where + ": expected a " + s.getTypeName() + ", got a " + a.type());
        }
        ObjectSchema elementSchema = schema instanceof AggregateSchema s ? s.getElementsSchema() : null;
        if (expected.isArray() && expected != byte[].class) {
            Class<?> component = expected.getComponentType();
            Object array = java.lang.reflect.Array.newInstance(component, a.elements().size());
            for (int i = 0; i < a.elements().size(); i++) {
                java.lang.reflect.Array.set(array, i, value(a.elements().get(i), component, null, elementSchema, where));
            }
            return array;
        }
        Class<?> et = elementType != null ? elementType : classOf(elementSchema);
        if (Number.class.isAssignableFrom(box(et))) {
            et = Object.class; // as JADE: an aggregate's numbers stay Long and Double, whatever the generic type says
        }
        List<Object> values = new ArrayList<>();
        for (AbsObject e : a.elements()) {
            values.add(value(e, et, null, elementSchema, where));
        }
        boolean set = AbsAggregate.SET.equals(a.type());
        if (expected == Object.class) {
            return set ? leapSet(values) : leapList(values);
        }
        if (expected.isAssignableFrom(jade.util.leap.ArrayList.class)) {
            return leapList(values);
        }
        if (expected.isAssignableFrom(jade.util.leap.HashSet.class)) {
            return leapSet(values);
        }
        if (expected.isAssignableFrom(ArrayList.class)) {
            return values;
        }
        if (expected.isAssignableFrom(LinkedHashSet.class)) {
            return new LinkedHashSet<>(values);
        }
        throw new OntologyException(where + ": expected " + expected.getSimpleName() + ", got a " + a.type());
    }

    private static jade.util.leap.List leapList(List<Object> values) {
        jade.util.leap.List l = new jade.util.leap.ArrayList();
        for (Object o : values) {
            l.add(o);
        }
        return l;
    }

    private static jade.util.leap.Set leapSet(List<Object> values) {
        jade.util.leap.Set s = new jade.util.leap.HashSet();
        for (Object o : values) {
            s.add(o);
        }
        return s;
    }

    private Class<?> classOf(ObjectSchema schema) throws OntologyException {
        if (schema == null) {
            return Object.class;
        }
        if (schema instanceof PrimitiveSchema) {
            switch (schema.getTypeName()) {
                case BasicOntology.STRING:
                    return String.class;
                case BasicOntology.INTEGER:
                    return Long.class;
                case BasicOntology.FLOAT:
                    return Double.class;
                case BasicOntology.BOOLEAN:
                    return Boolean.class;
                case BasicOntology.DATE:
                    return Date.class;
                case BasicOntology.BYTE_SEQUENCE:
                    return byte[].class;
                default:
                    return Object.class;
            }
        }
        Class<?> c = onto.getClassForElement(schema.getTypeName());
        return c == null ? Object.class : c;
    }

    private static Object primitive(Object v, Class<?> expected, String where) throws OntologyException {
        Class<?> e = box(expected);
        if (e == Object.class) {
            if (v instanceof Integer i) {
                return i.longValue(); // SL's integers are Long in JADE
            }
            if (v instanceof Float f) {
                return f.doubleValue();
            }
            return v instanceof Instant t ? Date.from(t) : v;
        }
        if (v instanceof Boolean b && (e == Predicate.class || e == TrueProposition.class || e == FalseProposition.class)) {
            Object proposition = b ? new TrueProposition() : new FalseProposition();
            if (e.isInstance(proposition)) {
                return proposition;
            }
        }
        if (v instanceof Long || v instanceof Integer) {
            long l = ((Number) v).longValue();
            if (e == Long.class) {
                return l;
            }
            if (e == Integer.class) {
                if (l < Integer.MIN_VALUE || l > Integer.MAX_VALUE) {
                    throw new OntologyException(where + ": " + l + " is out of the range of an int");
                }
                return (int) l;
            }
            if (e == Short.class) {
                if (l < Short.MIN_VALUE || l > Short.MAX_VALUE) {
                    throw new OntologyException(where + ": " + l + " is out of the range of a short");
                }
                return (short) l;
            }
        }
        if (v instanceof Number n) {
            if (e == Double.class) {
                return n.doubleValue();
            }
            if (e == Float.class) {
                return n.floatValue();
            }
        }
        if (v instanceof Instant t && e == Date.class) {
            return Date.from(t);
        }
        if (e.isInstance(v)) {
            return v;
        }
        throw new OntologyException(where + ": expected " + expected.getSimpleName() + ", got " + kind(v));
    }

    private static Class<?> box(Class<?> c) {
        return java.lang.invoke.MethodType.methodType(c).wrap().returnType();
    }

    private static AbsObject arg(AbsCompound c, int i, int arity) throws OntologyException {
        if (c.isNamed()) {
            throw new OntologyException(c.name() + " takes positional arguments");
        }
        if (c.slots().size() != arity) {
            throw new OntologyException(c.name() + " takes " + arity + " argument(s), got " + c.slots().size());
        }
        return c.slots().get(i).value();
    }

    /** The basic ontology's elements, or null when the symbol is not one of them. */
    private Object basic(AbsCompound c, String where) throws OntologyException {
        switch (c.name()) {
            case "agent-identifier": {
                AbsObject name = c.get("name");
                if (name == null) {
                    throw new OntologyException("missing mandatory slot :name of agent-identifier");
                }
                AID aid = new AID((String) value(name, String.class, null, null, "slot :name of agent-identifier"), AID.ISGUID);
                for (AbsCompound.Slot s : c.slots()) {
                    if (!List.of("name", "addresses", "resolvers").contains(s.name())) {
                        if (s.value() instanceof AbsPrimitive p) {
                            aid.addUserDefinedSlot(s.name(), String.valueOf(p.value())); // an AID's own slots
                        }
                        continue;
                    }
                    if (s.value() instanceof AbsAggregate a) {
                        for (AbsObject e : a.elements()) {
                            if (s.name().equals("addresses")) {
                                aid.addAddresses((String) value(e, String.class, null, null, "slot :addresses of agent-identifier"));
                            } else if (s.name().equals("resolvers")) {
                                aid.addResolvers((AID) value(e, AID.class, null, null, "slot :resolvers of agent-identifier"));
                            }
                        }
                    }
                }
                return aid;
            }
            case "action":
                return new Action((AID) value(arg(c, 0, 2), AID.class, null, null, "argument 1 of action"),
                        (Concept) value(arg(c, 1, 2), Concept.class, null, null, "argument 2 of action"));
            case "done":
                return new Done((Concept) value(arg(c, 0, 1), Concept.class, null, null, "argument 1 of done"));
            case "result":
                return new Result((Concept) value(arg(c, 0, 2), Concept.class, null, null, "argument 1 of result"),
                        value(arg(c, 1, 2), Object.class, null, null, "argument 2 of result"));
            case "=":
                return new Equals(value(arg(c, 0, 2), Object.class, null, null, "argument 1 of ="),
                        value(arg(c, 1, 2), Object.class, null, null, "argument 2 of ="));
            case "true":
                return new TrueProposition();
            case "false":
                return new FalseProposition();
            default:
                return null;
        }
    }

    private Object bean(AbsCompound c, String where) throws OntologyException {
        String name = c.name();
        ObjectSchema schema = onto.getSchema(name);
        if (schema == null || schema instanceof PrimitiveSchema || schema instanceof AggregateSchema) {
            throw new OntologyException(where + ": no schema in ontology " + onto.getName() + " for symbol " + name);
        }
        Class<?> cls = onto.getClassForElement(name);
        if (cls == null) {
            throw new OntologyException(where + ": no Java class for " + name + " in ontology " + onto.getName());
        }
        if (cls.isEnum()) {
            AbsObject n = c.isNamed() ? c.get(BeanOntology.ENUM_NAME) : (c.slots().isEmpty() ? null : c.slots().get(0).value());
            if (!(n instanceof AbsPrimitive p) || !(p.value() instanceof String constant)) {
                throw new OntologyException(where + ": " + name + " needs its :" + BeanOntology.ENUM_NAME + " (a string)");
            }
            for (Object k : cls.getEnumConstants()) {
                if (((Enum<?>) k).name().equals(constant)) {
                    return k;
                }
            }
            throw new OntologyException(where + ": " + constant + " is not a constant of " + cls.getName());
        }
        String[] names = schema.getNames();
        if (!c.isNamed() && c.slots().size() > names.length) {
            throw new OntologyException(name + " takes at most " + names.length + " argument(s), got " + c.slots().size());
        }
        // A named slot the schema does not have is ignored, as JADE ignores it (content-music-shop shows it).
        Object obj = instantiate(cls, name);
        for (int i = 0; i < names.length; i++) {
            String slot = names[i];
            AbsObject abs = c.isNamed() ? c.get(slot) : (i < c.slots().size() ? c.slots().get(i).value() : null);
            if (abs == null) {
                if (validate && schema.isMandatory(slot)) {
                    throw new OntologyException("missing mandatory slot :" + slot + " of " + name);
                }
                continue;
            }
            ObjectSchema slotSchema = schema.getSchema(slot);
            String at = "slot :" + slot + " of " + name;
            if (slotSchema instanceof AggregateSchema) {
                if (!(abs instanceof AbsAggregate a)) {
                    throw new OntologyException(at + ": expected a " + slotSchema.getTypeName());
                }
                if (validate) {
                    cardinality(schema, slot, a.elements().size());
                }
            }
            Ontology.Property p = onto.property(cls, slot);
            Object value = value(abs, p.type(), p.elementType(), slotSchema, at);
            if (validate && slotSchema instanceof ConceptSchema cs && !(value instanceof AID)) {
                ObjectSchema actual = schemaOf(value.getClass());
                if (actual != null && !isBase(cs) && !cs.isAssignableFrom(actual)) {
                    throw new OntologyException(at + ": expected " + cs.getTypeName() + ", got " + actual.getTypeName());
                }
            }
            try {
                p.set(obj, value);
            } catch (InvocationTargetException e) {
                throw new OntologyException(at + ": the setter refused the value: " + e.getCause(), e.getCause());
            } catch (ReflectiveOperationException | IllegalArgumentException e) {
                throw new OntologyException(at + ": cannot be set: " + e, e);
            }
        }
        return obj;
    }

    private static Object instantiate(Class<?> cls, String name) throws OntologyException {
        try {
            Constructor<?> ctor = cls.getDeclaredConstructor();
            ctor.setAccessible(true);
            return ctor.newInstance();
        } catch (InvocationTargetException e) {
            throw new OntologyException(name + ": the constructor of " + cls.getName() + " failed: " + e.getCause(), e.getCause());
        } catch (ReflectiveOperationException | RuntimeException e) {
            throw new OntologyException(name + ": " + cls.getName() + " needs an accessible no-argument constructor", e);
        }
    }
}
