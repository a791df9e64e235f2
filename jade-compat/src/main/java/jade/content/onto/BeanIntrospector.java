package jade.content.onto;

/** The introspector of JADE's {@link BeanOntology}: slots are JavaBean properties. */
public class BeanIntrospector implements Introspector {
    private static final long serialVersionUID = 1L;
}
