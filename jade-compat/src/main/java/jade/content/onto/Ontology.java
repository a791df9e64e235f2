package jade.content.onto;

import io.concord.core.content.AbsObject;
import io.concord.jadecompat.internal.ContentOntology;
import jade.content.schema.ObjectSchema;

import java.lang.reflect.Method;
import java.lang.reflect.ParameterizedType;
import java.lang.reflect.Type;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;

/**
 * A vocabulary, as JADE's: schemas by name, each with the Java class its values map to, and base
 * ontologies whose schemas it includes (every ontology here also understands the basic one's
 * elements: primitives, aggregates, {@code agent-identifier}, {@code action}, {@code done},
 * {@code result}, {@code =}, {@code true}, {@code false}). A class's slots are read and written
 * through its JavaBean properties: slot {@code lease-time} is {@code getLeaseTime}/{@code setLeaseTime}
 * ({@code isX} for a boolean), as JADE's {@code ReflectiveIntrospector} does; aggregates are
 * {@code jade.util.leap.List}/{@code Set} or {@code java.util.List}/{@code Set}, as the setter takes.
 */
public class Ontology implements jade.util.leap.Serializable, ContentOntology {
    private static final long serialVersionUID = 1L;

    private final String name;
    private final Ontology[] bases;
    private final Introspector introspector;
    private final Map<String, ObjectSchema> schemas = new LinkedHashMap<>();
    private final Map<String, Class<?>> classes = new HashMap<>();
    private final Map<Class<?>, ObjectSchema> byClass = new HashMap<>();
    private final transient Map<Class<?>, Map<String, Property>> properties = new ConcurrentHashMap<>();

    /**
     * One slot's accessors on a class: a getter and a setter, or, for an aggregate in JADE's older
     * bean style, {@code getAllX()} (an iterator), {@code addX(element)} and {@code clearAllX()}.
     */
    record Property(Method getter, Method setter, Class<?> elementType, Method clearer) {
        Property(Method getter, Method setter, Class<?> elementType) {
            this(getter, setter, elementType, null);
        }

        /** Whether the slot is read with {@code getAllX} and written with {@code addX}. */
        boolean adder() {
            return getter.getReturnType() == jade.util.leap.Iterator.class || getter.getReturnType() == java.util.Iterator.class;
        }

        /** The class the value read from content must have before {@link #set}. */
        Class<?> type() {
            return adder() ? java.util.List.class : setter.getParameterTypes()[0];
        }

        /** The slot's value (a list of the elements for an iterator getter). */
        Object get(Object target) throws ReflectiveOperationException {
            Object v = getter.invoke(target);
            if (v instanceof java.util.Iterator<?> it) {
                List<Object> out = new ArrayList<>();
                it.forEachRemaining(out::add);
                return out;
            }
            return v;
        }

        /** Sets the slot (adding each element for an adder). */
        void set(Object target, Object value) throws ReflectiveOperationException {
            if (!adder()) {
                setter.invoke(target, value);
                return;
            }
            if (clearer != null) {
                clearer.invoke(target);
            }
            for (Object o : (java.util.Collection<?>) value) {
                setter.invoke(target, o);
            }
        }
    }

    /** An ontology extending that one (usually {@code BasicOntology.getInstance()}). */
    public Ontology(String name, Ontology base) {
        this(name, base == null ? new Ontology[0] : new Ontology[]{base}, null);
    }

    /** An ontology with no base other than the basic elements; the introspector is not consulted. */
    public Ontology(String name, Introspector introspector) {
        this(name, new Ontology[0], introspector);
    }

    /** An ontology extending that one; the introspector is not consulted. */
    public Ontology(String name, Ontology base, Introspector introspector) {
        this(name, base == null ? new Ontology[0] : new Ontology[]{base}, introspector);
    }

    /** An ontology extending those; the introspector is not consulted. */
    public Ontology(String name, Ontology[] bases, Introspector introspector) {
        this.name = name;
        this.bases = bases == null ? new Ontology[0] : bases.clone();
        this.introspector = introspector;
    }

    /** Its name, the value of a message's {@code :ontology}. */
    public String getName() {
        return name;
    }

    /** The introspector given to the constructor, or null. */
    public Introspector getIntrospector() {
        return introspector;
    }

    /** Adds a schema with no Java class (its values can be written from and read into abstract form only). */
    public void add(ObjectSchema schema) throws OntologyException {
        add(schema, null);
    }

    /** Adds a schema and the class its values map to. */
    public void add(ObjectSchema schema, Class javaClass) throws OntologyException {
        if (schema == null) {
            throw new OntologyException("null schema");
        }
        schemas.put(schema.getTypeName(), schema);
        if (javaClass != null) {
            classes.put(schema.getTypeName(), javaClass);
            byClass.put(javaClass, schema);
        }
    }

    /** The schema of that name, here or in a base ontology, or null. */
    public ObjectSchema getSchema(String name) throws OntologyException {
        ObjectSchema s = schemas.get(name);
        if (s != null) {
            return s;
        }
        for (Ontology b : bases) {
            s = b.getSchema(name);
            if (s != null) {
                return s;
            }
        }
        return null;
    }

    /** The schema of that class, here or in a base ontology, or null. */
    public ObjectSchema getSchema(Class javaClass) throws OntologyException {
        ObjectSchema s = byClass.get(javaClass);
        if (s != null) {
            return s;
        }
        for (Ontology b : bases) {
            s = b.getSchema(javaClass);
            if (s != null) {
                return s;
            }
        }
        return null;
    }

    /** The class of the element of that name, here or in a base ontology, or null. */
    public Class getClassForElement(String name) throws OntologyException {
        Class<?> c = classes.get(name);
        if (c != null) {
            return c;
        }
        for (Ontology b : bases) {
            c = b.getClassForElement(name);
            if (c != null) {
                return c;
            }
        }
        return null;
    }

    /** Names of the concepts (and agent actions) of this ontology and its bases. */
    public java.util.List getConceptNames() {
        return names(jade.content.schema.ConceptSchema.class);
    }

    /** Names of the agent actions of this ontology and its bases. */
    public java.util.List getActionNames() {
        return names(jade.content.schema.AgentActionSchema.class);
    }

    /** Names of the predicates of this ontology and its bases. */
    public java.util.List getPredicateNames() {
        return names(jade.content.schema.PredicateSchema.class);
    }

    private List<String> names(Class<?> kind) {
        List<String> out = new ArrayList<>();
        for (Ontology b : bases) {
            out.addAll(b.names(kind));
        }
        for (ObjectSchema s : schemas.values()) {
            if (kind.isInstance(s) && !out.contains(s.getTypeName())) {
                out.add(s.getTypeName());
            }
        }
        return out;
    }

    @Override
    public String toString() {
        return "Ontology " + name;
    }

    /** The abstract descriptor of a Java object, checked against the schemas. */
    public jade.content.abs.AbsObject fromObject(Object value) throws OntologyException {
        return io.concord.jadecompat.internal.AbsConvert.fromCore(toAbs(value), this, false);
    }

    /** The Java object of an abstract descriptor, checked against the schemas. */
    public Object toObject(jade.content.abs.AbsObject abs) throws OntologyException, UngroundedException {
        return fromAbs(io.concord.jadecompat.internal.AbsConvert.toCore(abs, this), true);
    }

    @Override
    public AbsObject toAbs(Object value) throws OntologyException {
        return new Mapping(this, true).toAbs(value);
    }

    @Override
    public Object fromAbs(AbsObject abs, boolean validate) throws OntologyException {
        return new Mapping(this, validate).fromAbs(abs);
    }

    /** Records a slot's accessors explicitly (BeanOntology: a slot named otherwise than its property). */
    void addProperty(Class<?> c, String slot, Method getter, Method setter, Class<?> elementType) {
        properties.computeIfAbsent(c, k -> new ConcurrentHashMap<>()).put(slot, new Property(getter, setter, elementType));
    }

    /**
     * JADE lets an ontology's concept slots be used as functions in content
     * ({@code AbsConceptSlotFunction}); concord-jade does not support them, and says so here
     * rather than accept content it could not read.
     */
    protected void useConceptSlotsAsFunctions() {
        throw new UnsupportedOperationException("ontology " + getName() + ": concept slots as functions (AbsConceptSlotFunction) "
                + "are not supported by concord-jade");
    }

    /** The accessors of that slot on that class: recorded, or found by JavaBean naming. */
    Property property(Class<?> c, String slot) throws OntologyException {
        for (Class<?> k = c; k != null; k = k.getSuperclass()) {
            Property p = recorded(k, slot);
            if (p != null) {
                return p;
            }
        }
        Map<String, Property> found = properties.computeIfAbsent(c, k -> new ConcurrentHashMap<>());
        Property p = found.get(slot);
        if (p == null) {
            p = byNaming(c, slot);
            found.put(slot, p);
        }
        return p;
    }

    private Property recorded(Class<?> c, String slot) {
        Map<String, Property> m = properties.get(c);
        Property p = m == null ? null : m.get(slot);
        if (p != null) {
            return p;
        }
        for (Ontology b : bases) {
            p = b.recorded(c, slot);
            if (p != null) {
                return p;
            }
        }
        return null;
    }

    private static Property byNaming(Class<?> c, String slot) throws OntologyException {
        StringBuilder base = new StringBuilder();
        boolean upper = true;
        for (char ch : slot.toCharArray()) {
            if (!Character.isLetterOrDigit(ch)) {
                upper = true;
                continue;
            }
            base.append(upper ? Character.toUpperCase(ch) : ch);
            upper = false;
        }
        Method getter = null;
        for (String prefix : new String[]{"get", "is"}) {
            getter = publicMethod(c, prefix + base, -1);
            if (getter != null) {
                break;
            }
        }
        if (getter == null) {
            Property all = allAndAdd(c, base.toString());
            if (all != null) {
                return all;
            }
            throw new OntologyException("no getter get" + base + "() for slot :" + slot + " in class " + c.getName());
        }
        Method setter = publicMethod(c, "set" + base, 1);
        if (setter != null && setter.getParameterTypes()[0] != getter.getReturnType()) {
            try {
                setter = c.getMethod(setter.getName(), getter.getReturnType());
            } catch (NoSuchMethodException e) {
                setter = null;
            }
        }
        if (setter == null) {
            throw new OntologyException("no setter set" + base + "(" + getter.getReturnType().getSimpleName()
                    + ") for slot :" + slot + " in class " + c.getName());
        }
        return new Property(getter, setter, elementType(getter.getGenericReturnType()));
    }

    /**
     * The public method of that name (its exact case first, then ignoring case, as JADE finds a
     * slot's accessors: a slot {@code NAME} is read with {@code getName}) with no parameters
     * ({@code arity} -1) or that many; null if none.
     */
    private static Method publicMethod(Class<?> c, String name, int arity) {
        Method caseless = null;
        for (Method m : c.getMethods()) {
            if (m.getParameterCount() != Math.max(arity, 0) || !m.getName().equalsIgnoreCase(name)) {
                continue;
            }
            if (m.getName().equals(name)) {
                return m;
            }
            if (caseless == null) {
                caseless = m;
            }
        }
        return caseless;
    }

    /** JADE's older aggregate accessors: {@code getAllX()}, {@code addX(e)}, {@code clearAllX()}. */
    private static Property allAndAdd(Class<?> c, String base) {
        Method all = publicMethod(c, "getAll" + base, -1);
        if (all == null || !java.util.Iterator.class.isAssignableFrom(all.getReturnType())) {
            return null;
        }
        Method add = publicMethod(c, "add" + base, 1);
        if (add == null) {
            return null;
        }
        // no clearer (null): elements are added to what the object has
        Method clear = publicMethod(c, "clearAll" + base, -1);
        Class<?> element = add.getParameterTypes()[0];
        return new Property(all, add, element == Object.class ? null : element, clear);
    }

    static Class<?> elementType(Type t) {
        if (t instanceof ParameterizedType p && p.getActualTypeArguments().length == 1
                && p.getActualTypeArguments()[0] instanceof Class<?> e) {
            return e;
        }
        return null;
    }
}
