package io.concord.layers.platform;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.TreeMap;

/**
 * A service an agent offers in the yellow pages (FIPA's service-description): a type, a name, and
 * optional properties, ontologies, languages and protocols.
 *
 * <p>As a search template, every field that is set must match: type and name exactly, each
 * property by value, and each listed ontology, language or protocol must be among the service's.
 */
public record ServiceDescription(String type, String name, Map<String, String> properties,
                                 List<String> ontologies, List<String> languages, List<String> protocols) {

    public ServiceDescription {
        // Sorted, in every JVM: Map.copyOf iterates in an order salted per JVM run, so the same
        // registration went on the wire with its properties in another order from run to run.
        properties = properties == null ? Map.of() : Collections.unmodifiableMap(new TreeMap<>(properties));
        ontologies = ontologies == null ? List.of() : List.copyOf(ontologies);
        languages = languages == null ? List.of() : List.copyOf(languages);
        protocols = protocols == null ? List.of() : List.copyOf(protocols);
    }

    /** A service of a type with a name. */
    public static ServiceDescription of(String type, String name) {
        return new ServiceDescription(Objects.requireNonNull(type, "type"), name, Map.of(), List.of(), List.of(), List.of());
    }

    /** A template that matches every service of a type. */
    public static ServiceDescription ofType(String type) {
        return new ServiceDescription(Objects.requireNonNull(type, "type"), null, Map.of(), List.of(), List.of(), List.of());
    }

    public ServiceDescription withProperty(String key, String value) {
        Map<String, String> p = new TreeMap<>(properties);
        p.put(key, value);
        return new ServiceDescription(type, name, p, ontologies, languages, protocols);
    }

    public ServiceDescription withOntology(String o) {
        return new ServiceDescription(type, name, properties, plus(ontologies, o), languages, protocols);
    }

    public ServiceDescription withLanguage(String l) {
        return new ServiceDescription(type, name, properties, ontologies, plus(languages, l), protocols);
    }

    public ServiceDescription withProtocol(String p) {
        return new ServiceDescription(type, name, properties, ontologies, languages, plus(protocols, p));
    }

    private static List<String> plus(List<String> l, String v) {
        ArrayList<String> r = new ArrayList<>(l);
        r.add(Objects.requireNonNull(v));
        return r;
    }

    /**
     * True if an agent with these services answers a search with these templates, as a FIPA DF
     * search does: it offers at least one service, and each template is matched by one of them.
     */
    public static boolean offersAll(List<ServiceDescription> services, List<ServiceDescription> templates) {
        if (services.isEmpty()) {
            return false;
        }
        for (ServiceDescription t : templates) {
            boolean any = false;
            for (ServiceDescription s : services) {
                any |= s.matches(t);
            }
            if (!any) {
                return false;
            }
        }
        return true;
    }

    /** True if this service satisfies the template (see the class comment). */
    public boolean matches(ServiceDescription template) {
        if (template.type != null && !template.type.equals(type)) {
            return false;
        }
        if (template.name != null && !template.name.equals(name)) {
            return false;
        }
        for (Map.Entry<String, String> e : template.properties.entrySet()) {
            if (!e.getValue().equals(properties.get(e.getKey()))) {
                return false;
            }
        }
        return ontologies.containsAll(template.ontologies) && languages.containsAll(template.languages)
                && protocols.containsAll(template.protocols);
    }
}
