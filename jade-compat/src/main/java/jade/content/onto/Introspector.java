package jade.content.onto;

/**
 * JADE's strategy for reading and writing an object's slots. Here every ontology reads and writes
 * JavaBean properties (a getter and a setter per slot), as JADE's {@link ReflectiveIntrospector} does;
 * an introspector passed to an ontology's constructor is accepted and not consulted.
 */
public interface Introspector extends jade.util.leap.Serializable {
}
