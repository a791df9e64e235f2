package jade.content.onto;

import jade.content.AgentAction;
import jade.content.Concept;
import jade.content.Predicate;
import jade.content.onto.annotations.AggregateSlot;
import jade.content.onto.annotations.Element;
import jade.content.onto.annotations.Slot;
import jade.content.onto.annotations.SuppressSlot;
import jade.content.schema.AgentActionSchema;
import jade.content.schema.ConceptSchema;
import jade.content.schema.ObjectSchema;
import jade.content.schema.PredicateSchema;
import jade.content.schema.TermSchema;
import jade.core.AID;

import java.io.File;
import java.io.IOException;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.net.JarURLConnection;
import java.net.URISyntaxException;
import java.net.URL;
import java.net.URLConnection;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.Enumeration;
import java.util.List;
import java.util.TreeSet;
import java.util.jar.JarEntry;
import java.util.jar.JarFile;

/**
 * An ontology built from JavaBeans, as JADE's {@code BeanOntology}: each class implementing
 * {@link Concept}, {@link AgentAction} or {@link Predicate} gets a schema named by its simple name
 * (or {@link Element#name()}), one slot per property (a public getter {@code getX}/{@code isX} with a
 * matching setter {@code setX}) unless {@link SuppressSlot}, named as the property (or
 * {@link Slot#name()}), in alphabetical order (or by {@link Slot#position()}); mandatory if {@link Slot#mandatory()}, if the type is a Java primitive, or if
 * {@link AggregateSlot#cardMin()} is above 0. Slot types: {@code String}, {@code int}/{@code long}/
 * {@code short} (and boxes), {@code float}/{@code double}, {@code boolean}, {@code Date},
 * {@code byte[]}, {@link AID}, another bean (added too when not yet in the ontology),
 * {@code jade.util.leap.List}/{@code Set} or {@code java.util.List}/{@code Set} of those (element
 * class from {@link AggregateSlot#type()} or the generic type), arrays of those (sequences; {@code byte[]} is a byte
 * sequence), enums (a concept named by the enum with a {@code name} slot, as JADE writes them), {@code Object} for any term.
 */
public class BeanOntology extends Ontology {
    private static final long serialVersionUID = 1L;

    /** An ontology extending the basic one. */
    public BeanOntology(String name) {
        this(name, BasicOntology.getInstance());
    }

    /** An ontology extending that one. */
    public BeanOntology(String name, Ontology base) {
        super(name, base, new BeanIntrospector());
    }

    /** An ontology extending those. */
    public BeanOntology(String name, Ontology[] bases) {
        super(name, bases, new BeanIntrospector());
    }

    /** Adds that bean class. */
    public void add(Class c) throws BeanOntologyException {
        add(c, true);
    }

    /**
     * Adds that bean class. With {@code buildHierarchy}, a superclass that is a bean too gets its own
     * schema, which becomes this one's super-schema (its slots first, as JADE orders them); without,
     * the inherited properties are this schema's own slots.
     */
    public void add(Class c, boolean buildHierarchy) throws BeanOntologyException {
        try {
            schemaFor(c, buildHierarchy);
        } catch (OntologyException e) {
            throw e instanceof BeanOntologyException b ? b : new BeanOntologyException(e.getMessage(), e);
        }
    }

    /** Adds every bean class (a {@link Concept}, {@link AgentAction} or {@link Predicate}) of that package. */
    public void add(String packageName) throws BeanOntologyException {
        add(packageName, true);
    }

    /** Adds every bean class of that package. */
    public void add(String packageName, boolean buildHierarchy) throws BeanOntologyException {
        List<Class<?>> found = classesOf(packageName);
        if (found.isEmpty()) {
            throw new BeanOntologyException("no ontology classes found in package " + packageName);
        }
        for (Class<?> c : found) {
            add(c, buildHierarchy);
        }
    }

    private ObjectSchema schemaFor(Class<?> c, boolean buildHierarchy) throws OntologyException {
        ObjectSchema existing = getSchema(c);
        if (existing != null) {
            return existing;
        }
        boolean action = AgentAction.class.isAssignableFrom(c);
        boolean predicate = Predicate.class.isAssignableFrom(c);
        if (!action && !predicate && !Concept.class.isAssignableFrom(c)) {
            throw new BeanOntologyException(c.getName() + " is neither a Concept, an AgentAction nor a Predicate");
        }
        Element e = c.getAnnotation(Element.class);
        String name = e != null && !Element.USE_CLASS_SIMPLE_NAME.equals(e.name()) ? e.name() : c.getSimpleName();
        if (getSchema(name) != null) {
            throw new BeanOntologyException("two schemas named " + name + " (" + c.getName() + ")");
        }
        ObjectSchema schema = action ? new AgentActionSchema(name) : predicate ? new PredicateSchema(name) : new ConceptSchema(name);
        add(schema, c); // before the slots: a bean may refer to itself
        List<Prop> props = properties(c);
        Class<?> parent = c.getSuperclass();
        if (buildHierarchy && parent != null && parent != Object.class
                && (Concept.class.isAssignableFrom(parent) || Predicate.class.isAssignableFrom(parent))) {
            ObjectSchema superSchema = schemaFor(parent, true);
            if (schema instanceof PredicateSchema ps && superSchema instanceof PredicateSchema sup) {
                ps.addSuperSchema(sup);
            } else if (schema instanceof ConceptSchema cs && superSchema instanceof ConceptSchema sup) {
                cs.addSuperSchema(sup);
            } else {
                throw new BeanOntologyException(c.getName() + " and its superclass " + parent.getName() + " are of different kinds");
            }
            java.util.Set<String> inherited = java.util.Set.of(superSchema.getNames());
            props.removeIf(p -> inherited.contains(p.slotName()));
        }
        boolean byPosition = props.stream().anyMatch(p -> p.slot() != null && p.slot().position() >= 0);
        if (byPosition) {
            // JADE orders the slots by position and still writes them by name (content-bean-slots shows it)
            props.sort(Comparator.comparingInt(p -> p.slot() == null ? Integer.MAX_VALUE : p.slot().position()));
        } else {
            props.sort(Comparator.comparing(Prop::slotName));
        }
        for (Prop p : props) {
            addSlot(schema, c, p);
        }
        return schema;
    }

    private record Prop(String slotName, Method getter, Method setter, Slot slot, AggregateSlot aggregate) {
    }

    private static List<Prop> properties(Class<?> c) throws BeanOntologyException {
        List<Prop> out = new ArrayList<>();
        for (io.concord.core.content.BeanAccessors.Accessor a : io.concord.core.content.BeanAccessors.of(c)) {
            Method m = a.getter();
            String n = m.getName();
            Method setter = a.setter();
            if (m.isAnnotationPresent(SuppressSlot.class)) {
                continue;
            }
            Slot slot = m.getAnnotation(Slot.class);
            if (slot != null && slot.manageAsSerializable()) {
                throw new BeanOntologyException(c.getName() + "." + n + ": @Slot(manageAsSerializable) is not supported");
            }
            String slotName = slot != null && !Slot.USE_METHOD_NAME.equals(slot.name()) ? slot.name() : a.name();
            out.add(new Prop(slotName, m, setter, slot, m.getAnnotation(AggregateSlot.class)));
        }
        return out;
    }

    private void addSlot(ObjectSchema schema, Class<?> owner, Prop p) throws OntologyException {
        Class<?> type = p.getter().getReturnType();
        boolean list = jade.util.leap.List.class.isAssignableFrom(type) || java.util.List.class.isAssignableFrom(type);
        boolean set = jade.util.leap.Set.class.isAssignableFrom(type) || java.util.Set.class.isAssignableFrom(type);
        Class<?> elementType = null;
        String where = owner.getName() + "." + p.getter().getName();
        if (type.isArray() && type != byte[].class) {
            // An array is a sequence of its component type, as JADE writes it
            AggregateSlot a = p.aggregate();
            elementType = type.getComponentType();
            int cardMin = a != null ? a.cardMin() : 0;
            int cardMax = a != null ? a.cardMax() : ObjectSchema.UNLIMITED;
            boolean mandatory = cardMin > 0 || (p.slot() != null && p.slot().mandatory());
            ObjectSchema es = slotSchema(elementType, where);
            if (!(es instanceof TermSchema)) {
                throw new BeanOntologyException(where + ": an array holds terms, not " + elementType.getSimpleName());
            }
            addAggregate(schema, p.slotName(), (TermSchema) es, cardMin, cardMax, "sequence", mandatory);
        } else if (list || set || jade.util.leap.Collection.class.isAssignableFrom(type) || java.util.Collection.class.isAssignableFrom(type)) {
            if (!list && !set) {
                throw new BeanOntologyException(where + ": an aggregate must be a List or a Set");
            }
            AggregateSlot a = p.aggregate();
            elementType = a != null && a.type() != Object.class ? a.type() : Ontology.elementType(p.getter().getGenericReturnType());
            int cardMin = a != null ? a.cardMin() : 0;
            int cardMax = a != null ? a.cardMax() : ObjectSchema.UNLIMITED;
            boolean mandatory = cardMin > 0 || (p.slot() != null && p.slot().mandatory());
            ObjectSchema es = elementType == null ? null : slotSchema(elementType, where);
            if (es != null && !(es instanceof TermSchema)) {
                throw new BeanOntologyException(where + ": an aggregate holds terms, not " + elementType.getSimpleName());
            }
            TermSchema elements = (TermSchema) es;
            addAggregate(schema, p.slotName(), elements, cardMin, cardMax, set ? "set" : "sequence", mandatory);
        } else {
            ObjectSchema s = slotSchema(type, where);
            boolean mandatory = type.isPrimitive() || (p.slot() != null && p.slot().mandatory());
            int optionality = mandatory ? ObjectSchema.MANDATORY : ObjectSchema.OPTIONAL;
            if (schema instanceof PredicateSchema ps) {
                ps.add(p.slotName(), s, optionality);
            } else if (s instanceof TermSchema t) {
                ((ConceptSchema) schema).add(p.slotName(), t, optionality);
            } else if (schema instanceof AgentActionSchema as && s instanceof PredicateSchema ps) {
                as.add(p.slotName(), ps, optionality);
            } else {
                throw new BeanOntologyException(where + ": a concept cannot hold a " + type.getSimpleName());
            }
        }
        addProperty(owner, p.slotName(), p.getter(), p.setter(), elementType);
    }

    private static void addAggregate(ObjectSchema schema, String name, TermSchema elements, int cardMin, int cardMax,
                                     String type, boolean mandatory) {
        int optionality = mandatory ? ObjectSchema.MANDATORY : ObjectSchema.OPTIONAL;
        if (schema instanceof PredicateSchema ps) {
            ps.add(name, elements, cardMin, cardMax, type, optionality);
        } else {
            ((ConceptSchema) schema).add(name, elements, cardMin, cardMax, type, optionality);
        }
    }

    private ObjectSchema slotSchema(Class<?> type, String where) throws OntologyException {
        String primitive = BasicOntology.primitiveName(type);
        if (primitive != null) {
            return BasicOntology.getInstance().getSchema(primitive);
        }
        if (type == AID.class) {
            return BasicOntology.getInstance().getSchema(BasicOntology.AID);
        }
        if (type == Object.class || type.isInterface()) {
            return new TermSchema(TermSchema.BASE_NAME) {
                private static final long serialVersionUID = 1L;
            };
        }
        if (Concept.class.isAssignableFrom(type) || Predicate.class.isAssignableFrom(type)) {
            return schemaFor(type, true);
        }
        if (type.isEnum()) {
            return enumSchema(type, where);
        }
        throw new BeanOntologyException(where + ": no schema for type " + type.getName());
    }

    /**
     * An enum's schema, as JADE makes it: a concept named by the enum's simple name with one
     * mandatory string slot {@code name}, the constant's name: {@code (Size :name LARGE)}.
     */
    private ObjectSchema enumSchema(Class<?> type, String where) throws OntologyException {
        ObjectSchema existing = getSchema(type);
        if (existing != null) {
            return existing;
        }
        if (getSchema(type.getSimpleName()) != null) {
            throw new BeanOntologyException(where + ": two schemas named " + type.getSimpleName() + " (" + type.getName() + ")");
        }
        ConceptSchema schema = new ConceptSchema(type.getSimpleName());
        add(schema, type);
        schema.add(ENUM_NAME, (TermSchema) BasicOntology.getInstance().getSchema(BasicOntology.STRING));
        return schema;
    }

    /** The slot of an enum's schema that holds the constant's name. */
    static final String ENUM_NAME = "name";

    private static List<Class<?>> classesOf(String packageName) throws BeanOntologyException {
        String path = packageName.replace('.', '/');
        ClassLoader loader = Thread.currentThread().getContextClassLoader();
        if (loader == null) {
            loader = BeanOntology.class.getClassLoader();
        }
        TreeSet<String> names = new TreeSet<>();
        try {
            Enumeration<URL> urls = loader.getResources(path);
            while (urls.hasMoreElements()) {
                URL url = urls.nextElement();
                URLConnection conn = url.openConnection();
                conn.setUseCaches(false);
                if (conn instanceof JarURLConnection jar) {
                    try (JarFile f = jar.getJarFile()) {
                        for (Enumeration<JarEntry> es = f.entries(); es.hasMoreElements(); ) {
                            String n = es.nextElement().getName();
                            if (n.startsWith(path + "/") && n.endsWith(".class") && n.indexOf('/', path.length() + 1) < 0) {
                                names.add(n.substring(path.length() + 1, n.length() - 6));
                            }
                        }
                    }
                } else if ("file".equals(url.getProtocol())) {
                    File[] files = new File(url.toURI()).listFiles();
                    if (files != null) {
                        for (File f : files) {
                            if (f.getName().endsWith(".class")) {
                                names.add(f.getName().substring(0, f.getName().length() - 6));
                            }
                        }
                    }
                }
            }
            List<Class<?>> out = new ArrayList<>();
            for (String n : names) {
                if (n.contains("$")) {
                    continue;
                }
                Class<?> c = Class.forName(packageName.isEmpty() ? n : packageName + "." + n, false, loader);
                if (!c.isInterface() && !Modifier.isAbstract(c.getModifiers())
                        && (Concept.class.isAssignableFrom(c) || Predicate.class.isAssignableFrom(c))) {
                    out.add(c);
                }
            }
            return out;
        } catch (IOException | URISyntaxException | ClassNotFoundException e) {
            throw new BeanOntologyException("cannot list the classes of package " + packageName + ": " + e, e);
        }
    }
}
